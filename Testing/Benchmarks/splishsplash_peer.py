#!/usr/bin/env python3
"""SPlisHSPlasH's DFSPH on ParaFluid's resting scenes (benchmark-only peer, never in the product).

Writes a SPlisHSPlasH scene for the validation program's still water (a 0.5 m column 0.5 m long,
four spacings wide, walls all round, Testing/SPH/Validation/Hydrostatic.cxx) at `across` particles
deep, runs SPHSimulator headless, and reads its VTK particle exports back: the largest speed over
sqrt(g H) in the last second, and the wall time. Bender & Koschier's volume maps are the walls
(SPlisHSPlasH's default), the lattice SPlisHSPlasH's own (particles d from the walls).

usage: splishsplash_peer.py <SPHSimulator> <work-dir> [--across 10,20,40] [--duration 10]
       [--max-error 0.1] [--viscosity 1e-6] [--viscosity-method 6]
Build of the peer: Testing/Benchmarks/README.md (SPlisHSPlasH).
"""
import argparse
import glob
import json
import math
import os
import struct
import subprocess
import time

GRAVITY = 9.81


def scene(across, duration, max_error, viscosity, method):
    depth, length = 0.5, 0.5
    d = depth / across
    width = 4 * d
    # SPlisHSPlasH fills a block's box from one spacing inside its corner, in steps of d, to one
    # spacing short of its far corner (its own convention with volume-map walls; ParaFluid's
    # (i + 1/2) d from the walls over-fills them: the column rose and left the walls).
    return {
        "Configuration": {
            "particleRadius": d / 2,
            "simulationMethod": 4,  # DFSPH
            "gravitation": [0, -GRAVITY, 0],
            "timeStepSize": 0.001,
            "cflMethod": 1,
            "cflFactor": 1.0,  # dt = 0.4 d / v_max, ParaFluid's CFL number 0.2 of h = 2 d
            "cflMaxTimeStepSize": 0.005,
            "stopAt": duration,
            "dataExportFPS": 20,
            "enableVTKExport": True,
            "particleAttributes": "velocity;density",
            "boundaryHandlingMethod": 2,  # Bender et al. 2019 volume maps
            "DFSPH": {
                "minIterations": 2,
                "maxIterations": 100,
                "maxError": max_error,  # percent
                "maxIterationsV": 100,
                "maxErrorV": 0.1,
                "enableDivergenceSolver": True,
            },
        },
        "Materials": [{"id": "Fluid", "density0": 1000, "viscosityMethod": method,
                       "viscosity": viscosity}],
        "RigidBodies": [{
            "geometryFile": "../models/UnitBox.obj",
            "translation": [length / 2, depth, width / 2],
            "scale": [length, 2 * depth, width],
            "isDynamic": False, "isWall": True, "mapInvert": True, "mapThickness": 0.0,
            "mapResolution": [20, 40, 4],
        }],
        "FluidBlocks": [{
            "denseMode": 0,
            "start": [0, 0, 0],
            "end": [length, depth, width],
        }],
    }


def read_vtk(path):
    """Positions and velocities of a SPlisHSPlasH legacy binary VTK particle file (big-endian)."""
    with open(path, "rb") as f:
        data = f.read()
    out = {}
    pos = 0

    def line():
        nonlocal pos
        end = data.index(b"\n", pos)
        text = data[pos:end].decode("ascii", "replace").strip()
        pos = end + 1
        return text

    count = 0
    while pos < len(data):
        text = line()
        if text.startswith("POINTS"):
            _, n, kind = text.split()
            count = int(n)
            size = 8 if kind == "double" else 4
            fmt = ">" + ("d" if size == 8 else "f") * 3 * count
            out["position"] = struct.unpack(fmt, data[pos:pos + 3 * count * size])
            pos += 3 * count * size
        elif text.startswith("CELLS"):
            n = int(text.split()[2])
            pos += 4 * n
        elif text.startswith("CELL_TYPES"):
            pos += 4 * int(text.split()[1])
        elif text.startswith("FIELD"):
            continue
        elif text and text.split()[0] in ("velocity", "density", "id") and len(text.split()) == 4:
            name, comps, n, kind = text.split()
            size = {"float": 4, "double": 8, "unsigned_int": 4, "int": 4}[kind]
            code = {"float": "f", "double": "d", "unsigned_int": "I", "int": "i"}[kind]
            total = int(comps) * int(n)
            out[name] = struct.unpack(">" + code * total, data[pos:pos + total * size])
            pos += total * size
    return out


def run(simulator, work, across, duration, max_error, viscosity, method):
    directory = os.path.join(work, f"still_{across}")
    os.makedirs(directory, exist_ok=True)
    scene_dir = os.path.join(os.path.dirname(os.path.dirname(simulator)), "data", "Scenes")
    scene_file = os.path.join(scene_dir, f"parafluid_still_{across}.json")
    with open(scene_file, "w") as f:
        json.dump(scene(across, duration, max_error, viscosity, method), f, indent=1)
    start = time.time()
    subprocess.run([simulator, "--no-gui", "--no-initial-pause", "--no-cache", "--output-dir", directory,
                    scene_file], check=True, stdout=subprocess.DEVNULL)
    seconds = time.time() - start
    frames = sorted(glob.glob(os.path.join(directory, "vtk", "*.vtk")),
                    key=lambda p: int(p.rsplit("_", 1)[1].split(".")[0]))
    reference = math.sqrt(GRAVITY * 0.5)
    last_second = frames[-21:]
    largest, particles = 0.0, 0
    for frame in last_second:
        v = read_vtk(frame)["velocity"]
        particles = len(v) // 3
        for i in range(particles):
            largest = max(largest, math.sqrt(v[3 * i] ** 2 + v[3 * i + 1] ** 2 + v[3 * i + 2] ** 2))
    return particles, seconds, largest / reference


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("simulator")
    parser.add_argument("work")
    parser.add_argument("--across", default="10,20,40")
    parser.add_argument("--duration", type=float, default=10.0)
    parser.add_argument("--max-error", type=float, default=0.1)
    parser.add_argument("--viscosity", type=float, default=1e-6)
    parser.add_argument("--viscosity-method", type=int, default=6)  # Weiler et al. 2018, implicit
    a = parser.parse_args()
    print("solver,across,particles,wall_seconds,largest_speed_over_sqrt_gH")
    for across in [int(x) for x in a.across.split(",")]:
        particles, seconds, speed = run(os.path.abspath(a.simulator), a.work, across, a.duration, a.max_error,
                                        a.viscosity, a.viscosity_method)
        print(f"SPlisHSPlasH-DFSPH,{across},{particles},{seconds:.1f},{speed:.3e}", flush=True)


if __name__ == "__main__":
    main()
