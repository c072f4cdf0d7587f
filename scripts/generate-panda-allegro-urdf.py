#!/usr/bin/env python3
"""Writes data/robots/panda_allegro/panda_allegro.urdf: a Franka Emika Panda carrying a Wonik Allegro Hand.

Our second built-in robot, generated from published numbers only (every one and its source in
docs/robot_model.md, "The second robot: panda_allegro"): the Panda's modified DH table, joint limits
and speeds and its vendor's capsule model of the links; the Allegro's (right hand) joint frames,
link lengths, limits and collision boxes. No third-party file is copied and no mesh is used: the
collision geometry is boxes, capped cylinders (capsules) and spheres, written as visuals too.
Run from the repository root; the output is deterministic. Only the Python standard library is used.
"""
import math
import sys
from pathlib import Path

# ---------------------------------------------------------------- small rigid-transform algebra
def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]

def identity():
    return [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]

def trans(x, y, z):
    t = identity(); t[0][3], t[1][3], t[2][3] = x, y, z
    return t

def rot(axis, angle):
    """Rotation by `angle` (rad) about the unit axis 'x', 'y' or 'z'."""
    c, s = math.cos(angle), math.sin(angle)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    t = identity(); t[i][i], t[i][j], t[j][i], t[j][j] = c, -s, s, c
    return t

def chain(*transforms):
    result = identity()
    for t in transforms:
        result = matmul(result, t)
    return result

def modified_dh(alpha, a, d):
    """Craig's convention with the joint angle at 0: RotX(alpha)·TransX(a)·TransZ(d) (rad, m)."""
    return chain(rot("x", alpha), trans(a, 0, 0), trans(0, 0, d))

def rpy(t):
    """URDF fixed-axis roll, pitch, yaw of a rotation: R = Rz(yaw)·Ry(pitch)·Rx(roll)."""
    pitch = math.asin(max(-1.0, min(1.0, -t[2][0])))
    if abs(math.cos(pitch)) > 1e-9:
        return math.atan2(t[2][1], t[2][2]), pitch, math.atan2(t[1][0], t[0][0])
    return 0.0, pitch, math.atan2(-t[0][1], t[1][1])  # gimbal lock: everything in yaw

def fmt(v):
    s = f"{v:.12f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s

def origin(t):
    xyz = " ".join(fmt(t[i][3]) for i in range(3))
    return f'<origin xyz="{xyz}" rpy="{" ".join(fmt(a) for a in rpy(t))}"/>'

def along(p0, p1):
    """Pose of a shape whose local z runs from p0 to p1 (metres), centred between them."""
    d = [p1[i] - p0[i] for i in range(3)]; length = math.sqrt(sum(v * v for v in d))
    z = [v / length for v in d]
    helper = [1.0, 0.0, 0.0] if abs(z[0]) < 0.9 else [0.0, 1.0, 0.0]
    x = [helper[1] * z[2] - helper[2] * z[1], helper[2] * z[0] - helper[0] * z[2], helper[0] * z[1] - helper[1] * z[0]]
    n = math.sqrt(sum(v * v for v in x)); x = [v / n for v in x]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]
    t = identity()
    for i in range(3):
        t[i][0], t[i][1], t[i][2] = x[i], y[i], z[i]
        t[i][3] = (p0[i] + p1[i]) / 2
    return t, length

# ---------------------------------------------------------------- URDF writing
out = []
COLOURS = {"arm": "0.92 0.92 0.90 1", "joint": "0.20 0.20 0.22 1", "hand": "0.15 0.15 0.16 1", "tip": "0.90 0.90 0.90 1"}

def link(name, shapes=(), colour="hand"):
    out.append(f'  <link name="{name}">')
    for pose, geometry in shapes:
        for tag in ("visual", "collision"):
            extra = f'<material name="{colour}"/>' if tag == "visual" else ""
            out.append(f"    <{tag}>{origin(pose)}<geometry>{geometry}</geometry>{extra}</{tag}>")
    out.append("  </link>")

def joint(name, kind, parent, child, t, axis=None, limits=None, effort=0.0, velocity=0.0):
    """A joint; `limits` (lower, upper) in rad, `velocity` in rad/s, `effort` in N·m."""
    out.append(f'  <joint name="{name}" type="{kind}">')
    out.append(f'    <parent link="{parent}"/><child link="{child}"/>{origin(t)}')
    if axis:
        out.append(f'    <axis xyz="{axis}"/>')
    if limits:
        lo, hi = limits
        out.append(f'    <limit lower="{fmt(lo)}" upper="{fmt(hi)}" effort="{fmt(effort)}" velocity="{fmt(velocity)}"/>')
    out.append("  </joint>")

def box(size):
    return f'<box size="{" ".join(fmt(v) for v in size)}"/>'

def cylinder(r, length):
    return f'<cylinder radius="{fmt(r)}" length="{fmt(length)}"/>'

def sphere(r):
    return f'<sphere radius="{fmt(r)}"/>'

def capsule(p0, p1, r):
    """A cylinder from p0 to p1 with spheres at both ends (URDF has no capsule)."""
    pose, length = along(p0, p1)
    return [(pose, cylinder(r, length)), (trans(*p0), sphere(r)), (trans(*p1), sphere(r))]

def capsule_at(centre, direction, length, r):
    """Franka's form of a capsule: its centre, axis direction and cylinder length (caps beyond it)."""
    half = [v * length / 2 for v in direction]
    return capsule([centre[i] - half[i] for i in range(3)], [centre[i] + half[i] for i in range(3)], r)

def box_at(centre, size):
    return (trans(*centre), box(size))

# ---------------------------------------------------------------- the Panda
# Franka Emika's published modified DH table (alpha, a, d), joint limits (rad) and maximum joint
# speeds (rad/s) and torques (N·m); the flange is 107 mm beyond joint 7 along its axis.
PANDA = [  # alpha, a, d, (lower, upper), speed, torque
    (0.0, 0.0, 0.333, (-2.8973, 2.8973), 2.1750, 87),
    (-math.pi / 2, 0.0, 0.0, (-1.7628, 1.7628), 2.1750, 87),
    (math.pi / 2, 0.0, 0.316, (-2.8973, 2.8973), 2.1750, 87),
    (math.pi / 2, 0.0825, 0.0, (-3.0718, -0.0698), 2.1750, 87),
    (-math.pi / 2, -0.0825, 0.384, (-2.8973, 2.8973), 2.6100, 12),
    (math.pi / 2, 0.0, 0.0, (-0.0175, 3.7525), 2.6100, 12),
    (math.pi / 2, 0.088, 0.0, (-2.8973, 2.8973), 2.6100, 12),
]
FLANGE = 0.107
X, Z = [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]
# Franka's capsule model of each link (centre, axis, cylinder length, radius; in the link's DH frame),
# with no safety margin. Two ends are cut where the model would reach past the real robot: link 1's
# lower cap stops at the base plate (the model's capsule reaches 60 mm below it, into the floor),
# and link 7's upper cap ends at the flange face (the model's reaches 13 mm beyond it, into the palm).
DIAGONAL = [math.cos(math.pi / 4), math.sin(math.pi / 4), 0.0]  # link 7's model is turned 45 deg about z
PANDA_SHAPES = [
    capsule_at([-0.075, 0, 0.06], X, 0.03, 0.06),  # link 0: the base housing behind joint 1
    capsule([0, 0, -0.273], [0, 0, -0.05], 0.06),  # link 1 (model: z -0.333..-0.05)
    capsule_at([0, 0, 0], Z, 0.12, 0.06),  # link 2: the shoulder
    capsule_at([0, 0, -0.145], Z, 0.15, 0.06),  # link 3: the upper arm
    capsule_at([0, 0, 0], Z, 0.12, 0.06),  # link 4: the elbow
    capsule_at([0, 0, -0.26], Z, 0.10, 0.06) + capsule_at([0, 0.08, -0.13], Z, 0.14, 0.025),  # link 5: forearm
    capsule_at([0, 0, -0.03], Z, 0.08, 0.05),  # link 6: the wrist
    capsule([0, 0, -0.06], [0, 0, FLANGE - 0.04], 0.04)  # link 7 (model: z -0.06..0.08) and its side boss
    + capsule_at([0.06 * DIAGONAL[0], 0.06 * DIAGONAL[1], 0.082], DIAGONAL, 0.01, 0.03),
]

out.append('<?xml version="1.0"?>')
out.append("<!-- Generated by scripts/generate-panda-allegro-urdf.py: do not edit by hand. -->")
out.append("<!-- Franka Emika Panda (its modified DH table) with a Wonik Allegro Hand (right) on its flange; docs/robot_model.md. -->")
out.append('<robot name="panda_allegro">')
for name, rgba in COLOURS.items():
    out.append(f'  <material name="{name}"><color rgba="{rgba}"/></material>')

link("panda_link0", PANDA_SHAPES[0], "arm")
for i, (alpha, a, d, limits, speed, torque) in enumerate(PANDA):
    joint(f"panda_joint{i + 1}", "revolute", f"panda_link{i}", f"panda_link{i + 1}", modified_dh(alpha, a, d), "0 0 1",
          limits, effort=torque, velocity=speed)
    link(f"panda_link{i + 1}", PANDA_SHAPES[i + 1], "arm" if i % 2 == 0 else "joint")
joint("panda_joint8", "fixed", "panda_link7", "panda_link8", trans(0, 0, FLANGE))
link("panda_link8")

# ---------------------------------------------------------------- the Allegro Hand (right), on the flange
# Palm frame = the Allegro's base frame: +z along the fingers (the finger bases lie at z = 0, the
# mounting face at z = -0.095), +y toward the index finger and the thumb, +x the palm normal on the
# grasp side (every flexion joint turns its finger toward +x). The palm's mounting face sits on the
# flange, turned -90 deg about the flange axis, so that the palm's y is the flange's x: reaching
# forward with the wrist unrolled (joints 1, 3, 5 near 0), the hand is upright, thumb up and palm to
# the left, as a right hand reaches for a can; the wrist's 88 mm offset lies on its little-finger side.
PALM_DEPTH = 0.095
joint("allegro_mount", "fixed", "panda_link8", "palm", chain(rot("z", -math.pi / 2), trans(0, 0, PALM_DEPTH)))
link("palm", [box_at([-0.0093, 0, -PALM_DEPTH / 2], [0.0408, 0.1130, PALM_DEPTH])])

# Published joint limits (rad): the spread joint, then the three flexion joints of a finger; the
# thumb's base rotation, its second base joint and its two flexion joints.
FINGER_LIMITS = [(-0.47, 0.47), (-0.196, 1.61), (-0.174, 1.709), (-0.227, 1.618)]
THUMB_LIMITS = [(0.263, 1.396), (-0.105, 1.163), (-0.189, 1.644), (-0.162, 1.719)]
# The published descriptions give no joint speed or torque of their own (the maker's writes 0); the
# widely used community fork writes 7 rad/s and an effort of 15 for every joint, which we keep.
HAND_SPEED, HAND_EFFORT = 7.0, 15.0
# Link cross-section (along the palm normal x across the finger) and lengths (m), the fingertip radius.
SECTION = (0.0196, 0.0275)
FINGER_LENGTHS = (0.0164, 0.054, 0.0384, 0.0387)  # spread link, proximal, medium, distal to the tip's end
THUMB_LENGTHS = (0.0177, 0.0514, 0.0543)  # second base link, proximal, distal to the tip's end
TIP_RADIUS = 0.012

def phalanx(length):
    """A published link box from the joint up to `length` along z."""
    return box_at([0, 0, length / 2], [SECTION[0], SECTION[1], length])

def tip_phalanx(length):
    """The last link: its box to the fingertip sphere's centre, the 12 mm sphere there."""
    return [phalanx(length - TIP_RADIUS), (trans(0, 0, length - TIP_RADIUS), sphere(TIP_RADIUS))]

def hand_joint(name, parent, child, t, axis, limits):
    joint(name, "revolute", parent, child, t, axis, limits, effort=HAND_EFFORT, velocity=HAND_SPEED)

def finger(name, base):
    """Index, middle or ring finger from its base frame in the palm (the published frames)."""
    spread, proximal, medium, distal = FINGER_LENGTHS
    # The spread joint turns the finger about its own length (z): a flexed finger swings sideways.
    hand_joint(f"{name}_abduction", "palm", f"{name}_knuckle", base, "0 0 1", FINGER_LIMITS[0])
    link(f"{name}_knuckle", [phalanx(spread)])
    hand_joint(f"{name}_proximal", f"{name}_knuckle", f"{name}_proximal_link", trans(0, 0, spread), "0 1 0", FINGER_LIMITS[1])
    link(f"{name}_proximal_link", [phalanx(proximal)])
    hand_joint(f"{name}_medium", f"{name}_proximal_link", f"{name}_medium_link", trans(0, 0, proximal), "0 1 0", FINGER_LIMITS[2])
    link(f"{name}_medium_link", [phalanx(medium)])
    hand_joint(f"{name}_distal", f"{name}_medium_link", f"{name}_distal_link", trans(0, 0, medium), "0 1 0", FINGER_LIMITS[3])
    link(f"{name}_distal_link", tip_phalanx(distal), "tip")

# Finger bases: the index and ring fingers 43.5 mm to either side of the middle one and 1.542 mm
# lower (the middle 0.7 mm higher than the palm's top), each tilted 5 deg outward about x.
DEG5 = math.radians(5)
finger("index", chain(trans(0, 0.0435, -0.001542), rot("x", -DEG5)))
finger("middle", trans(0, 0, 0.0007))
finger("ring", chain(trans(0, -0.0435, -0.001542), rot("x", DEG5)))

# Thumb: the base rotation joint (about an axis close to the palm's z, toward opposition as it
# grows) sits inside the palm's index-side lower part; its frame is the published one (roll, pitch,
# yaw 0, -95, -90 deg), and it turns about its -x.
THUMB_BASE = chain(trans(-0.0182, 0.019333, -0.045987), rot("z", -math.pi / 2), rot("y", -math.radians(95)))
hand_joint("thumb_base", "palm", "thumb_base_link", THUMB_BASE, "-1 0 0", THUMB_LIMITS[0])
# The thumb-base housing: the published 35.8 x 34 x 45.5 mm block, placed as the community fork of the
# maker's description places it, reaching from this joint to the next (docs/robot_model.md).
link("thumb_base_link", [box_at([-0.0179, 0.009, 0.0145], [0.0358, 0.034, 0.0455])])
# Its second base joint turns the thumb about its own length, like the fingers' spread joints.
hand_joint("thumb_abduction", "thumb_base_link", "thumb_knuckle", trans(-0.027, 0.005, 0.0399), "0 0 1", THUMB_LIMITS[1])
link("thumb_knuckle", [phalanx(THUMB_LENGTHS[0])])
hand_joint("thumb_proximal", "thumb_knuckle", "thumb_proximal_link", trans(0, 0, THUMB_LENGTHS[0]), "0 1 0", THUMB_LIMITS[2])
link("thumb_proximal_link", [phalanx(THUMB_LENGTHS[1])])
hand_joint("thumb_distal", "thumb_proximal_link", "thumb_distal_link", trans(0, 0, THUMB_LENGTHS[1]), "0 1 0", THUMB_LIMITS[3])
link("thumb_distal_link", tip_phalanx(THUMB_LENGTHS[2]), "tip")

out.append("</robot>")
target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("data/robots/panda_allegro/panda_allegro.urdf")
target.parent.mkdir(parents=True, exist_ok=True)
target.write_text("\n".join(out) + "\n")
print(f"wrote {target}")
