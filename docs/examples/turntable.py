#!/usr/bin/env python3
"""Renders a turntable of a glTF model into a folder of EXRs: VIEWS views, the camera turned
360 / VIEWS degrees about the model between views, each with depth and normal layers. The
model is loaded once; a render of each view follows the last.

    python3 docs/examples/turntable.py DamagedHelmet.glb turntable/ --views 36 --spp 64
"""
import argparse
import pathlib
import sys
import time

import vkpt


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model", help="a .gltf or .glb file")
    parser.add_argument("folder", help="where view_000.exr, view_001.exr, ... go")
    parser.add_argument("--views", type=int, default=36)
    parser.add_argument("--width", type=int, default=512)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--backend", default="auto", choices=["auto", "cpu", "vulkan"])
    parser.add_argument("--environment", default="", help="an .hdr or .exr lighting the model")
    args = parser.parse_args()

    folder = pathlib.Path(args.folder)
    folder.mkdir(parents=True, exist_ok=True)
    try:
        scene = vkpt.Scene(args.model, backend=args.backend, environment=args.environment)
    except vkpt.Error as e:
        sys.exit(f"turntable: {e}")
    start = time.monotonic()
    for view in range(args.views):
        camera = vkpt.Camera(orbit=360.0 * view / args.views)
        render = scene.render(camera, width=args.width, spp=args.spp, aovs=["depth", "normal"])
        path = folder / f"view_{view:03d}.exr"
        render.save(str(path))
        print(f"{path}: {render.spp} spp in {render.seconds:.2f} s")
    seconds = time.monotonic() - start
    print(f"{args.views} views on {scene.device} in {seconds:.1f} s ({args.views / seconds:.2f} views/s)")


if __name__ == "__main__":
    main()
