// The computation of shared_math.comp, also compiled as C++ by test_gpu.cpp, so both
// sides evaluate literally the same expression for each input index.
#ifdef __cplusplus
VKPT_BEGIN_NAMESPACE
#endif

VKPT_FN MathOut Evaluate(uint i) {
  MathOut o;
  o.hash = Pcg4d(uvec4(i, 3u * i + 1u, 7u, 11u));
  o.rand = Random4(5u, i, 2u, 3u);
  vec3 n = normalize(vec3(o.rand.x, o.rand.y, o.rand.z) * 2.0f - 1.0f + vec3(0.0f, 0.0f, 1e-3f));
  vec3 local = SampleCosineHemisphere(o.rand.w, o.rand.x);
  vec3 d = FrameToWorld(FrameFromNormal(n), local);
  o.dir = vec4(d, CosineHemispherePdf(local.z));
  vec2 b = SampleUniformTriangle(o.rand.y, o.rand.w);
  vec3 origin = vec3(o.rand.x, o.rand.y, -2.0f);
  vec3 ray = normalize(vec3(o.rand.z - 0.5f, o.rand.w - 0.5f, 1.0f));
  float tBox = IntersectBox(vec3(0.0f), vec3(1.0f), origin, SafeInverse(ray), 100.0f);
  vec3 hit = IntersectTriangle(vec3(0.0f, 0.0f, 0.5f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f), origin, ray, 100.0f);
  o.misc = vec4(b.x, b.y, tBox, hit.x);
  o.sobol = vec4(Sample2D(7u, i, i >> 3u, 2u), Sample2D(7u, i >> 4u, i, 5u));
  return o;
}

#ifdef __cplusplus
VKPT_END_NAMESPACE
#endif
