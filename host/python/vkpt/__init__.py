"""vkpt: a physically based path tracer for glTF 2.0 scenes, on Vulkan or the CPU.

    import vkpt
    scene = vkpt.Scene("DamagedHelmet.glb")
    render = scene.render(spp=64, aovs=["depth", "normal"])
    image = render.image            # float32, height x width x 3, linear radiance
    depth = render.aovs["depth"]    # float32, height x width x 1
    render.save("helmet.exr")       # the image with its AOVs as EXR layers

See docs/python.md.
"""

from ._vkpt import (AnimationInfo, BvhInfo, Camera, CameraInfo, Device, Error, LightInfo, MaterialInfo,
                    MaterialTextureInfo, MeshInfo, NodeInfo, PrimitiveInfo, ProgressiveRender, Render, Scene,
                    SceneStats, SettingError, __version__, devices)

__all__ = ["AnimationInfo", "BvhInfo", "Camera", "CameraInfo", "Device", "Error", "LightInfo", "MaterialInfo",
           "MaterialTextureInfo", "MeshInfo", "NodeInfo", "PrimitiveInfo", "ProgressiveRender", "Render", "Scene",
           "SceneStats", "SettingError", "__version__", "devices"]

from ._arguments import shorten_type_errors as _shorten_type_errors

for _cls, _methods in ((Scene, ("__init__", "render", "begin", "update")), (Camera, ("__init__",)), (Render, ("save",))):
    for _method in _methods:
        _shorten_type_errors(_cls, _method)
del _cls, _methods, _method, _shorten_type_errors
