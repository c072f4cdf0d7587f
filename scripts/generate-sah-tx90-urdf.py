#!/usr/bin/env python3
"""Writes data/robots/sah_tx90/sah_tx90.urdf: a Staubli TX90 carrying a Schunk Anthropomorphic Hand.

Every number and its source is in docs/robot_model.md (the TX90's modified DH table; the SAH frames of
the authors' model, converted to the positive-flexion convention). Collision geometry is made of
primitives sized from the published dimensions (the bounds of the authors' hand meshes). Run from the repository root; the output is deterministic.
Only the Python standard library is used.
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

def rot_x(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]]

def rot_z(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]

def rot_axis(axis, deg):
    n = math.sqrt(sum(v * v for v in axis)); x, y, z = (v / n for v in axis)
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg)); C = 1 - c
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s, 0],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s, 0],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C, 0], [0, 0, 0, 1]]

def mm(t):
    """A transform given in millimetres, returned in metres."""
    r = [row[:] for row in t]
    for i in range(3):
        r[i][3] = t[i][3] / 1000.0
    return r

def modified_dh(alpha, a, theta, d):
    """Craig's convention: RotX(alpha)·TransX(a)·RotZ(theta)·TransZ(d) (mm, deg)."""
    return matmul(matmul(matmul(rot_x(alpha), trans(a, 0, 0)), rot_z(theta)), trans(0, 0, d))

def rpy(t):
    """URDF fixed-axis roll, pitch, yaw of a rotation: R = Rz(yaw)·Ry(pitch)·Rx(roll)."""
    r = t
    pitch = math.asin(max(-1.0, min(1.0, -r[2][0])))
    if abs(math.cos(pitch)) > 1e-9:
        roll = math.atan2(r[2][1], r[2][2]); yaw = math.atan2(r[1][0], r[0][0])
    else:  # gimbal lock: put everything in yaw
        roll = 0.0; yaw = math.atan2(-r[0][1], r[1][1])
    return roll, pitch, yaw

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
COLOURS = {"arm": "0.93 0.55 0.13 1", "hand": "0.55 0.57 0.62 1", "tip": "0.25 0.25 0.28 1"}

def shapes_xml(shapes, colour):
    lines = []
    for pose, geometry in shapes:
        for tag in ("visual", "collision"):
            extra = f'<material name="{colour}"/>' if tag == "visual" else ""
            lines.append(f"    <{tag}>{origin(pose)}<geometry>{geometry}</geometry>{extra}</{tag}>")
    return "\n".join(lines)

def link(name, shapes=(), colour="hand"):
    out.append(f'  <link name="{name}">')
    if shapes:
        out.append(shapes_xml(shapes, colour))
    out.append("  </link>")

def joint(name, kind, parent, child, t, axis=None, limits=None, mimic=None, velocity=1.0):
    out.append(f'  <joint name="{name}" type="{kind}">')
    out.append(f'    <parent link="{parent}"/><child link="{child}"/>{origin(t)}')
    if axis:
        out.append(f'    <axis xyz="{axis}"/>')
    if limits:
        lo, hi = limits
        out.append(f'    <limit lower="{fmt(math.radians(lo))}" upper="{fmt(math.radians(hi))}" effort="100" velocity="{fmt(velocity)}"/>')
    if mimic:
        out.append(f'    <mimic joint="{mimic}" multiplier="1" offset="0"/>')
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

def translation(t):
    return [t[0][3], t[1][3], t[2][3]]

# ---------------------------------------------------------------- the TX90 (docs/robot_model.md, "Kinematics")
TX90 = [  # alpha, a, theta offset, d (mm, deg); limits (deg); max speed (deg/s)
    (0, 0, 0, 478, (-180, 180), 400),
    (-90, 50, -90, 50, (-130, 147.5), 400),
    (0, 425, 90, 0, (-145, 145), 430),
    (90, 0, 0, 425, (-270, 270), 540),
    (-90, 0, 0, 0, (-115, 140), 475),
    (90, 0, 0, 100, (-270, 270), 760),
]
# Envelope radii (m) of each moving link; the base is a pedestal of its own.
ARM_RADIUS = [0.105, 0.085, 0.075, 0.065, 0.055, 0.045]

out.append('<?xml version="1.0"?>')
out.append("<!-- Generated by scripts/generate-sah-tx90-urdf.py: do not edit by hand. -->")
out.append("<!-- Staubli TX90 (its modified DH table, docs/robot_model.md) with a Schunk Anthropomorphic Hand on its flange. -->")
out.append('<robot name="sah_tx90">')
for name, rgba in COLOURS.items():
    out.append(f'  <material name="{name}"><color rgba="{rgba}"/></material>')

link("tx90_base_link", [(trans(0, 0, 0.15), cylinder(0.12, 0.30))], "arm")
frames = [modified_dh(a, d_a, th, d) for (a, d_a, th, d, _, _) in TX90]
for i, (alpha, a, theta, d, limits, speed) in enumerate(TX90):
    # Joint origin = RotX(alpha)·TransX(a)·RotZ(theta)·TransZ(d); the joint turns about its local z.
    joint(f"tx90_joint_{i + 1}", "revolute", "tx90_base_link" if i == 0 else f"tx90_link_{i}",
          f"tx90_link_{i + 1}", mm(frames[i]), "0 0 1", limits, velocity=math.radians(speed))
# Link geometry: a capsule from the link's joint to the next joint's origin (in the link frame),
# plus the motor housings. Link 6 is the flange; the palm carries the hand's geometry.
arm_shapes = {}
for i in range(6):
    r = ARM_RADIUS[i]
    if i < 5:
        p1 = translation(mm(frames[i + 1]))
        arm_shapes[i] = capsule([0, 0, 0], p1, r) if math.dist([0, 0, 0], p1) > 1e-9 else [(identity(), sphere(r))]
    else:
        arm_shapes[i] = [(trans(0, 0, -0.01), cylinder(r, 0.02))]
# Link 1: the shoulder housing hangs below joint 2 down to the pedestal.
arm_shapes[0] = [(trans(0, 0, -0.09), cylinder(0.115, 0.18))] + capsule([0, 0, 0], translation(mm(frames[1])), 0.105)
# Link 2 (upper arm) reaches from the shoulder (joint 2, offset 50 mm along its axis) to the elbow.
arm_shapes[1] = capsule([0, 0, 0], translation(mm(frames[2])), 0.07)
# Link 3 (elbow): housing around joint 3 and the start of the forearm.
arm_shapes[2] = [(identity(), sphere(0.08))] + capsule([0, 0, 0], [0, -0.20, 0.0], 0.06)
# Link 4 (forearm) turns about its z; its frame sits at the wrist centre (d4 = 425 mm from the
# elbow), so the forearm runs along -z back toward the elbow part of link 3.
# Radii are slim enough for the elbow to fold to the published 136 deg of the tasks' start.
arm_shapes[3] = capsule([0, 0, -0.225], [0, 0, -0.03], 0.055)
# Link 5: the wrist housing around the wrist centre.
# It stops 10 mm short of the flange so it never touches the palm.
arm_shapes[4] = [(identity(), sphere(0.06))] + capsule([0, 0, 0], [0, -0.04, 0], 0.05)

for i in range(6):
    link(f"tx90_link_{i + 1}", arm_shapes[i], "arm")

# ---------------------------------------------------------------- the SAH (docs/robot_model.md), palm = flange
# Palm frame: +z along the fingers, +y toward thumb/index, +x the palm normal on the grasp side.
joint("tx90_flange_to_palm", "fixed", "tx90_link_6", "palm", identity())
# Palm box: the published outline (x -44.7..36.9, y -60.0..63.2, z -7.0..158.9 mm) without the
# knuckle region above z 128 mm (the fingers' abduction blocks stand there), so flexed proximal
# phalanges do not sit permanently inside the palm.
PALM = (-0.0447, 0.0369, -0.0600, 0.0632, -0.007, 0.128)
palm_centre = [(PALM[0] + PALM[1]) / 2, (PALM[2] + PALM[3]) / 2, (PALM[4] + PALM[5]) / 2]
palm_size = [PALM[1] - PALM[0], PALM[3] - PALM[2], PALM[5] - PALM[4]]
link("palm", [(trans(*palm_centre), box(palm_size))])

PROXIMAL, MEDIUM, DISTAL_TIP = 67.8, 30.0, 29.5  # mm
# Finger cross-sections (docs/robot_model.md, "Collision geometry"): the real hand's proximal
# phalanx is about 37 mm thick from back to pad, its abduction block about 40 x 33 x 25 mm (along
# the finger x across the finger x along the palm normal). The block's 33 mm is taken as the
# finger's width: the proximal phalanx is a capsule of that diameter about the joint axis line plus
# a palmar pad that brings its thickness to 37 mm. The medium phalanx keeps the older sizes (no
# published cross-section), the distal one its published 10 mm fingertip radius.
FINGER_WIDTH, PROXIMAL_THICKNESS = 33.0, 37.0  # mm
ABDUCTION_BLOCK = (40.0, 33.0, 25.0)  # mm, in the knuckle frame: along the finger, width, palm normal
RADIUS = {"proximal": FINGER_WIDTH / 2000, "medium": 0.0105, "distal": 0.0100, "tip": 0.010}
PROXIMAL_PAD_DEPTH = (PROXIMAL_THICKNESS - FINGER_WIDTH / 2) / 1000  # m below the joint axis line
ABDUCTION, PROXIMAL_LIMITS, MEDIUM_LIMITS = (-15, 15), (-4, 75), (4, 75)

def finger(name, parent, base):
    """One finger from its base frame (the authors' frames, flexion turned to positive)."""
    joint(f"{name}_abduction", "revolute", parent, f"{name}_knuckle", base, "0 0 1", ABDUCTION, velocity=math.radians(360))
    # The abduction block, centred on the crossing of the abduction and proximal flexion axes.
    link(f"{name}_knuckle", [(identity(), box([v / 1000 for v in ABDUCTION_BLOCK]))])
    # Kautham flexes about -z of these frames; our flexion is positive, so the axes point along -z.
    joint(f"{name}_proximal", "revolute", f"{name}_knuckle", f"{name}_proximal_link", mm(rot_x(-90)), "0 0 -1", PROXIMAL_LIMITS, velocity=math.radians(360))
    # Phalanges: a capsule about the joint axis line plus a pad on the palmar side (-y of these
    # frames, where flexion moves). The proximal pad, as wide as the finger, spans 26..52 mm of the
    # 67.8 mm phalanx: toward both joints the phalanx narrows to the capsule, so that the real
    # hand's full flexion stays free (flexed to 75 deg the pad clears the palm's top, and a fully
    # curled medium and distal phalanx clears the pad; tests/tasks/hand_self_collision_test.cpp).
    link(f"{name}_proximal_link", capsule([0, 0, 0], [PROXIMAL / 1000, 0, 0], RADIUS["proximal"]) +
         [(trans(0.039, -PROXIMAL_PAD_DEPTH / 2, 0), box([0.026, PROXIMAL_PAD_DEPTH, FINGER_WIDTH / 1000]))])
    joint(f"{name}_medium", "revolute", f"{name}_proximal_link", f"{name}_medium_link", mm(trans(PROXIMAL, 0, 0)), "0 0 -1", MEDIUM_LIMITS, velocity=math.radians(360))
    link(f"{name}_medium_link", capsule([0, 0, 0], [MEDIUM / 1000, 0, 0], RADIUS["medium"]) +
         [(trans(0.015, -0.008, 0), box([0.022, 0.016, 0.019]))])
    joint(f"{name}_distal", "revolute", f"{name}_medium_link", f"{name}_distal_link",
          mm(matmul(trans(MEDIUM, 0, 0), rot_z(-90))), "0 0 -1", MEDIUM_LIMITS, mimic=f"{name}_medium", velocity=math.radians(360))
    # The fingertip point (0, 29.5, 0) of the distal frame is the centre of a 10 mm sphere, which reaches
    # 39.5 mm (the distal mesh's pad 39.3); a box fills the pad side of the phalanx.
    link(f"{name}_distal_link", [(along([0, 0, 0], [0, DISTAL_TIP / 1000, 0])[0], cylinder(RADIUS["distal"], DISTAL_TIP / 1000)),
                                 (trans(0, DISTAL_TIP / 1000, 0), sphere(RADIUS["tip"])),
                                 (trans(0.00625, 0.01675, 0), box([0.0125, 0.0255, 0.017]))], "tip")

# Thumb base (joint 0): turns the whole thumb about the palm z axis through (-3, 27.1) mm; Kautham's
# q0 runs -90..0, ours 0..90 toward opposition, hence the -z axis.
joint("thumb_base", "revolute", "palm", "thumb_base_link", mm(trans(-3, 27.1, 0)), "0 0 -1", (0, 90), velocity=math.radians(360))
# The thumb-base block (published bounds x -27.3..20.0, y 18.5..111.0, z 0.7..101.3 in the palm frame),
# expressed in the joint's frame.
# Its y extent stops at 92 mm (published 111) to leave the thumb's knuckle, at y 114, free to turn:
# 5.5 mm short of the proximal phalanx's capsule (radius half the finger width) around it.
THUMB_BASE_Y_END = 114.0 - FINGER_WIDTH / 2 - 5.5
TB = (-27.3 + 3, 20.0 + 3, 18.5 - 27.1, THUMB_BASE_Y_END - 27.1, 0.7, 101.3)
link("thumb_base_link", [(trans((TB[0] + TB[1]) / 2000, (TB[2] + TB[3]) / 2000, (TB[4] + TB[5]) / 2000),
                          box([(TB[1] - TB[0]) / 1000, (TB[3] - TB[2]) / 1000, (TB[5] - TB[4]) / 1000]))])
finger("thumb", "thumb_base_link", mm(matmul(trans(-6, 86.9, 97), rot_axis((0.419, -0.419, 0.805), 102.31))))
finger("index", "palm", mm(matmul(trans(-4.3, 40.165, 145.43), rot_axis((0.707, 0.0125, 0.707), 178.56))))
finger("middle", "palm", mm(matmul(trans(-4.3, 0, 150.143), rot_axis((0.707, 0, 0.707), 180))))
finger("ring", "palm", mm(matmul(trans(-4.3, -40.165, 145.43), rot_axis((0.707, -0.0121, 0.707), 181.39))))

out.append("</robot>")
target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("data/robots/sah_tx90/sah_tx90.urdf")
target.write_text("\n".join(out) + "\n")
print(f"wrote {target}")
