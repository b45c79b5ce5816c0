// The shared headers' scene access (shaders/shared/backend_contract.h lists the macros) over a
// RenderScene named `scene`: what the CPU renderer, and host code that samples the
// scene as the renderers do (the light table reading emissive textures), compile them with.
#pragma once

#include "render/render_scene.h"

#define VKPT_SCENE_PARAM const ::vkpt::internal::RenderScene &scene,
#define VKPT_SCENE_ARG scene,
#define VKPT_TRIANGLE(i) scene.triangles[i]
#define VKPT_MATERIAL(i) scene.materials[i]
#define VKPT_LIGHT(i) scene.lights[i]
#define VKPT_LIGHT_CDF(i) scene.lights[i].cdf
#define VKPT_LIGHT_NODE(i) scene.lightTree[i]
#define VKPT_LIGHT_TREE (!scene.lightTree.empty())
#define VKPT_SHADING(i) scene.shading[i]
#define VKPT_VERTEX_COLORS (!scene.vertexColors.empty())
#define VKPT_VERTEX_COLORS_OF(i) scene.vertexColors[i]
#define VKPT_TEXTURES (!scene.textureRefs.empty())
#define VKPT_TEXTURE(i) scene.textures[i]
#define VKPT_TEXEL_WORD(i) scene.texels[i]
#define VKPT_TEXEL_DECODE(i) scene.texelDecode[i]
#define VKPT_TEXEL_UNORM(b) scene.texelDecode[::vkpt::shader::kTexelDecodeLinear + (b)]
#define VKPT_TEXTURE_REF(i) scene.textureRefs[i]
#define VKPT_UVS_OF(i) scene.uvs[i]
#define VKPT_NORMAL_MAPS (!scene.tangents.empty())
#define VKPT_ALPHA scene.alphaTested
#define VKPT_TANGENTS_OF(i) scene.tangents[i]
#define VKPT_ENV_TEXEL(i) scene.environment.texels[i]
#define VKPT_ENV_CDF(i) scene.environment.cdf[i]
