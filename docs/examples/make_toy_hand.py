#!/usr/bin/env python3
"""Writes a small third-party-like robot for docs/bring_your_own_robot.md and the tests: a
three-finger toy hand (thumb with an opposition joint, two fingers; distal joints mimic their
proximal ones) on a short four-joint arm with a wrist camera, as a ROS-style package OUT/toy_hand/ with
urdf/toy_hand.urdf and binary STL visual meshes in meshes/. Collision geometry is boxes.

  make_toy_hand.py OUT                  arm + hand, visuals as package://toy_hand/meshes/*.stl
  make_toy_hand.py OUT --hand-only      the hand alone on a fixed mount
  make_toy_hand.py OUT --extra-arm      plus a second arm and a head (for joints held by a task)
  make_toy_hand.py OUT --relative-meshes  visuals as ../meshes/*.stl (no package search path)
  make_toy_hand.py OUT --postures N     also OUT/toy_hand_postures.csv: N hand postures (degrees)
"""
import argparse
import math
import os
import random
import struct

DEG = math.pi / 180.0


def box_triangles(sx, sy, sz):
    """12 triangles of a box centred at the origin, outward normals."""
    hx, hy, hz = sx / 2, sy / 2, sz / 2
    v = [(x, y, z) for x in (-hx, hx) for y in (-hy, hy) for z in (-hz, hz)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = []
    for a, b, c, d in faces:
        tris.append((v[a], v[b], v[c]))
        tris.append((v[a], v[c], v[d]))
    return tris


def write_stl(path, triangles):
    with open(path, "wb") as out:
        out.write(b"toy_hand box mesh".ljust(80, b" "))
        out.write(struct.pack("<I", len(triangles)))
        for p, q, r in triangles:
            u = [q[i] - p[i] for i in range(3)]
            w = [r[i] - p[i] for i in range(3)]
            n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
            length = math.sqrt(sum(c * c for c in n)) or 1.0
            out.write(struct.pack("<3f", *(c / length for c in n)))
            for vertex in (p, q, r):
                out.write(struct.pack("<3f", *vertex))
            out.write(struct.pack("<H", 0))


class Urdf:
    def __init__(self, name, package_dir, mesh_prefix):
        self.lines = ['<?xml version="1.0"?>', f'<robot name="{name}">']
        self.meshes = os.path.join(package_dir, "meshes")
        self.mesh_prefix = mesh_prefix

    def link(self, name, size=None, centre=(0, 0, 0)):
        if size is None:
            self.lines.append(f'  <link name="{name}"/>')
            return
        write_stl(os.path.join(self.meshes, f"{name}.stl"), box_triangles(*size))
        xyz = " ".join(f"{c:g}" for c in centre)
        dims = " ".join(f"{c:g}" for c in size)
        self.lines += [
            f'  <link name="{name}">',
            f'    <visual><origin xyz="{xyz}"/><geometry><mesh filename="{self.mesh_prefix}{name}.stl"/></geometry></visual>',
            f'    <collision><origin xyz="{xyz}"/><geometry><box size="{dims}"/></geometry></collision>',
            "  </link>"]

    def joint(self, name, kind, parent, child, xyz, axis=(0, 0, 1), limit=None, mimic=None):
        self.lines.append(f'  <joint name="{name}" type="{kind}">')
        self.lines.append(f'    <parent link="{parent}"/><child link="{child}"/>')
        self.lines.append(f'    <origin xyz="{" ".join(f"{c:g}" for c in xyz)}"/>')
        if kind != "fixed":
            self.lines.append(f'    <axis xyz="{" ".join(f"{c:g}" for c in axis)}"/>')
        if limit:
            self.lines.append(f'    <limit lower="{limit[0] * DEG:.6f}" upper="{limit[1] * DEG:.6f}" effort="10" velocity="1"/>')
        if mimic:
            self.lines.append(f'    <mimic joint="{mimic}" multiplier="1" offset="0"/>')
        self.lines.append("  </joint>")

    def text(self):
        return "\n".join(self.lines + ["</robot>", ""])


def arm(u, prefix, parent, at):
    u.joint(f"{prefix}yaw", "revolute", parent, f"{prefix}link1", at, (0, 0, 1), (-170, 170))
    u.link(f"{prefix}link1", (0.06, 0.06, 0.2), (0, 0, 0.1))
    u.joint(f"{prefix}shoulder", "revolute", f"{prefix}link1", f"{prefix}link2", (0, 0, 0.2), (0, 1, 0), (-100, 100))
    u.link(f"{prefix}link2", (0.05, 0.05, 0.3), (0, 0, 0.15))
    u.joint(f"{prefix}elbow", "revolute", f"{prefix}link2", f"{prefix}link3", (0, 0, 0.3), (0, 1, 0), (-150, 150))
    u.link(f"{prefix}link3", (0.04, 0.04, 0.25), (0, 0, 0.125))
    u.joint(f"{prefix}wrist", "revolute", f"{prefix}link3", f"{prefix}flange", (0, 0, 0.25), (0, 0, 1), (-170, 170))
    u.link(f"{prefix}flange", (0.05, 0.05, 0.01), (0, 0, 0.005))
    # A wrist camera whose bracket touches the palm at the home pose (and only near it).
    u.joint(f"{prefix}camera_mount", "fixed", f"{prefix}link3", f"{prefix}camera", (0.05, 0.04, 0.262))
    u.link(f"{prefix}camera", (0.03, 0.03, 0.03))
    return f"{prefix}flange"


def hand(u, parent):
    u.joint("palm_mount", "fixed", parent, "palm", (0, 0, 0.012))
    u.link("palm", (0.09, 0.07, 0.02), (0, 0, 0.01))
    u.joint("thumb_rotate", "revolute", "palm", "thumb_base_link", (-0.04, 0, 0.021), (0, 0, 1), (-30, 60))
    u.link("thumb_base_link", (0.016, 0.016, 0.01), (0, 0, 0.005))
    u.joint("thumb_flex", "revolute", "thumb_base_link", "thumb_proximal", (0, 0, 0.011), (0, 1, 0), (0, 90))
    u.link("thumb_proximal", (0.015, 0.015, 0.04), (0, 0, 0.021))
    u.joint("thumb_tip", "revolute", "thumb_proximal", "thumb_distal", (0, 0, 0.043), (0, 1, 0), (0, 90), "thumb_flex")
    u.link("thumb_distal", (0.013, 0.013, 0.03), (0, 0, 0.016))
    for name, y in (("finger1", 0.02), ("finger2", -0.02)):
        u.joint(f"{name}_spread", "revolute", "palm", f"{name}_base_link", (0.03, y, 0.021), (1, 0, 0), (-15, 15))
        u.link(f"{name}_base_link", (0.016, 0.016, 0.01), (0, 0, 0.005))
        u.joint(f"{name}_flex", "revolute", f"{name}_base_link", f"{name}_proximal", (0, 0, 0.011), (0, -1, 0), (0, 90))
        u.link(f"{name}_proximal", (0.015, 0.015, 0.04), (0, 0, 0.021))
        u.joint(f"{name}_tip", "revolute", f"{name}_proximal", f"{name}_distal", (0, 0, 0.043), (0, -1, 0), (0, 90), f"{name}_flex")
        u.link(f"{name}_distal", (0.013, 0.013, 0.03), (0, 0, 0.016))


HAND_JOINTS = ["thumb_rotate", "thumb_flex", "finger1_spread", "finger1_flex", "finger2_spread", "finger2_flex"]


def postures(path, count, seed):
    """Key grasps of the toy hand blended with noise: open-close of all fingers (the first
    synergy), thumb-finger pinch against the other fingers (the second), spread."""
    rng = random.Random(seed)
    with open(path, "w") as out:
        out.write(",".join(HAND_JOINTS) + "\n")
        for _ in range(count):
            close = rng.uniform(0, 1)
            pinch = rng.uniform(-0.5, 0.5)
            spread = rng.gauss(0, 0.3)
            values = [rng.uniform(-30, 60),
                      75 * close + 15 * pinch + rng.gauss(0, 2),
                      12 * spread + rng.gauss(0, 1), 75 * close - 10 * pinch + rng.gauss(0, 2),
                      -12 * spread + rng.gauss(0, 1), 75 * close - 25 * pinch + rng.gauss(0, 2)]
            limits = [(-30, 60), (0, 90), (-15, 15), (0, 90), (-15, 15), (0, 90)]
            out.write(",".join(f"{min(max(v, lo), hi):.3f}" for v, (lo, hi) in zip(values, limits)) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--hand-only", action="store_true")
    parser.add_argument("--extra-arm", action="store_true")
    parser.add_argument("--relative-meshes", action="store_true")
    parser.add_argument("--postures", type=int, default=0)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    package = os.path.join(args.out, "toy_hand")
    os.makedirs(os.path.join(package, "urdf"), exist_ok=True)
    os.makedirs(os.path.join(package, "meshes"), exist_ok=True)
    prefix = "../meshes/" if args.relative_meshes else "package://toy_hand/meshes/"
    u = Urdf("toy_hand", package, prefix)
    if args.hand_only:
        u.link("mount", (0.05, 0.05, 0.012), (0, 0, 0.006))
        hand(u, "mount")
    else:
        u.link("base", (0.2, 0.2, 0.1), (0, 0, 0.05))
        hand(u, arm(u, "arm_", "base", (0, 0, 0.1)))
        if args.extra_arm:
            u.joint("spare_mount", "fixed", "base", "spare_base", (0, -0.5, 0))
            u.link("spare_base", (0.2, 0.2, 0.1), (0, 0, 0.05))
            arm(u, "spare_", "spare_base", (0, 0, 0.1))
            u.joint("head_pan", "continuous", "base", "head", (-0.2, 0, 0.5), (0, 0, 1))
            u.link("head", (0.1, 0.1, 0.1), (0, 0, 0))
    with open(os.path.join(package, "urdf", "toy_hand.urdf"), "w") as out:
        out.write(u.text())
    if args.postures:
        postures(os.path.join(args.out, "toy_hand_postures.csv"), args.postures, args.seed)


if __name__ == "__main__":
    main()
