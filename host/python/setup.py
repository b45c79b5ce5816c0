# The wheel of the vkpt package as CMake built it, compiled module and type stubs included
# (`cmake --build build --target wheel`), for `pip install build/dist/vkpt-*.whl`. In a virtual environment made with
# --system-site-packages (NumPy comes from Debian) and offline: docs/python.md.
from setuptools import setup
from setuptools.dist import Distribution


class CompiledDistribution(Distribution):
    """A wheel for this Python and platform: the package holds a compiled module."""

    def has_ext_modules(self):
        return True


setup(
    name="vkpt",
    version="@PROJECT_VERSION@",
    description="A physically based path tracer for glTF 2.0 scenes, on Vulkan or the CPU",
    packages=["vkpt"],
    package_data={"vkpt": ["_vkpt*.so", "*.pyi", "py.typed"]},
    python_requires=">=3.9",
    install_requires=["numpy"],
    distclass=CompiledDistribution,
)
