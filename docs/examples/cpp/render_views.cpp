// render_views SCENE OUT [cpu]: renders SCENE from four sides, turning the camera about
// the scene, into OUT.0.exr … OUT.3.exr with a depth layer; the scene is loaded once.
#include <cstdio>
#include <string>

#include <vkpt/vkpt.h>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: render_views SCENE OUT [cpu]\n");
    return 2;
  }
  try {
    vkpt::SceneOptions sceneOptions;
    if (argc > 3 && std::string(argv[3]) == "cpu") sceneOptions.backend = vkpt::Backend::Cpu;
    vkpt::Scene scene(argv[1], sceneOptions);

    vkpt::RenderOptions options;
    options.width = 128;
    options.spp = 16;
    options.aovs = {"depth"};
    for (int view = 0; view < 4; ++view) {
      vkpt::Camera camera;  // the file's first camera, turned
      camera.orbitDegrees = 90.0 * view;
      const vkpt::RenderResult result = scene.Render(camera, options);
      const vkpt::Image& depth = result.aovs.at("depth");
      const std::string path = std::string(argv[2]) + "." + std::to_string(view) + ".exr";
      vkpt::Save(result, path);
      std::printf("%s: %u x %u, %u spp on %s, centre depth %.3f\n", path.c_str(), result.image.width,
                  result.image.height, result.spp, result.engine.c_str(), depth.At(depth.width / 2, depth.height / 2));
    }
  } catch (const vkpt::Error& e) {
    std::fprintf(stderr, "render_views: %s\n", e.what());
    return 1;
  }
  return 0;
}
