#!/usr/bin/env python3
"""Writes config/worlds/cluttered.json: an L-shaped office corridor turned
23 degrees off the axes, with furniture, ceiling clutter (lamps, a duct, a
beam across, a pipe), rooms with desks and shelves seen through open
doorways, a slanted end wall, and the laser errors of real sensors
(doc/simulator.md, "Laser errors"). Issue 16's cluttered world: everything is
laid out in each leg's own coordinates (s along it, d to its left) and turned
into world coordinates here, so the file stays readable as numbers.

Usage: scripts/make-cluttered-world.py [OUT]   (default config/worlds/cluttered.json)
"""
import json
import math
import sys

HEADING_DEG = 23.0
WIDTH = 2.4
HEIGHT = 2.8
LEGS = [20.0, 16.5]  # the second leg runs on past the slanted end wall

u = (math.cos(math.radians(HEADING_DEG)), math.sin(math.radians(HEADING_DEG)))
left0 = (-u[1], u[0])
dirs = [u, (-left0[0], -left0[1])]  # a right turn
P0 = (0.0, 0.0)
P1 = (P0[0] + LEGS[0] * u[0], P0[1] + LEGS[0] * u[1])
P2 = (P1[0] + LEGS[1] * dirs[1][0], P1[1] + LEGS[1] * dirs[1][1])
starts = [P0, P1]


def r3(v):
    return round(v, 6)


def at(leg, s, d):
    """World [x, y] of the point s along leg `leg` and d to its left."""
    o, t = starts[leg], dirs[leg]
    n = (-t[1], t[0])
    return [r3(o[0] + s * t[0] + d * n[0]), r3(o[1] + s * t[1] + d * n[1])]


def yaw(leg):
    return r3(math.degrees(math.atan2(dirs[leg][1], dirs[leg][0])))


def box(kind, leg, s, d, along, across, z0, z1):
    return {"kind": kind, "shape": "box", "centre": at(leg, s, d), "size_m": [along, across],
            "yaw_deg": yaw(leg), "z_min_m": z0, "z_max_m": z1}


def cylinder(kind, leg, s, d, r, z0, z1):
    return {"kind": kind, "shape": "cylinder", "centre": at(leg, s, d), "radius_m": r,
            "z_min_m": z0, "z_max_m": z1}


clutter = [
    # leg 0: along the walls
    box("radiator", 0, 3.0, -1.12, 1.0, 0.12, 0.15, 0.75),
    cylinder("column", 0, 6.0, 0.95, 0.15, 0.0, HEIGHT),
    cylinder("bin", 0, 9.0, -0.95, 0.2, 0.0, 0.8),
    box("cabinet", 0, 12.0, 0.93, 1.2, 0.5, 0.0, 2.0),
    box("shelf", 0, 16.5, -0.97, 1.0, 0.4, 0.0, 1.8),
    # leg 0: the ceiling
    box("duct", 0, 10.0, 0.85, 16.0, 0.4, 2.35, 2.65),
    box("beam", 0, 10.6, 0.0, 0.3, WIDTH, 2.5, HEIGHT),
    # leg 1
    box("pillar", 1, 4.0, 0.95, 0.6, 0.4, 0.0, 1.2),
    cylinder("bin", 1, 7.5, 0.97, 0.22, 0.0, 1.0),
    box("cabinet", 1, 10.0, -0.93, 1.2, 0.5, 0.0, 2.0),
    box("pipe", 1, 7.0, -1.0, 12.0, 0.1, 2.5, 2.6),
    # rooms seen through the doorways
    box("desk", 0, 4.5, 3.5, 1.4, 0.7, 0.0, 0.75),
    box("shelf", 0, 3.2, 5.05, 1.0, 0.4, 0.0, 1.9),
    box("desk", 0, 13.5, -3.0, 1.4, 0.7, 0.0, 0.75),
    box("cabinet", 0, 12.2, -4.5, 0.8, 0.5, 0.0, 1.2),
    box("desk", 1, 7.0, 3.3, 1.4, 0.7, 0.0, 0.75),
]
for s in (2.0, 5.0, 8.0, 14.0, 17.0):
    clutter.append(box("lamp", 0, s, -0.3, 1.2, 0.3, 2.68, 2.74))
for s in (2.0, 5.0, 8.0, 11.0):
    clutter.append(box("lamp", 1, s, 0.0, 1.2, 0.3, 2.68, 2.74))

# The slanted end wall across leg 1, 30 degrees off square, seen from the
# corridor (corners counter-clockwise from the free space).
slant = math.tan(math.radians(30.0))
end_s = 15.5
a = at(1, end_s - 1.2 * slant, -1.2)
b = at(1, end_s + 1.2 * slant, 1.2)
end_wall = {"kind": "wall", "corners": [a + [0.0], a + [HEIGHT], b + [HEIGHT], b + [0.0]]}
# Make sure it faces the robot: (c1 - c0) x (c3 - c0) must point back along leg 1.
c0, c1, c3 = end_wall["corners"][0], end_wall["corners"][1], end_wall["corners"][3]
e1 = [c1[i] - c0[i] for i in range(3)]
e3 = [c3[i] - c0[i] for i in range(3)]
normal = (e1[1] * e3[2] - e1[2] * e3[1], e1[2] * e3[0] - e1[0] * e3[2])
if normal[0] * dirs[1][0] + normal[1] * dirs[1][1] > 0:
    end_wall["corners"] = [b + [0.0], b + [HEIGHT], a + [HEIGHT], a + [0.0]]

world = {
    "name": "cluttered",
    "description": (
        "L-shaped office corridor (legs 20 m and 16.5 m, 2.4 m wide, 2.8 m high) turned 23 "
        "degrees off the axes, with a slanted end wall 30 degrees off square, three rooms "
        "with desks, shelves and a cabinet seen through open doorways, five doors, "
        "furniture along the walls (radiator, column, bins, cabinets, shelf, pillar), "
        "ceiling clutter (lamps, a duct, a beam across, a pipe) and the laser errors of "
        "real sensors. Issue 16's cluttered world; written by "
        "scripts/make-cluttered-world.py."),
    "corridors": [{
        "name": "L",
        "centreline": [[r3(p[0]), r3(p[1])] for p in (P0, P1, P2)],
        "width_m": WIDTH,
        "height_m": HEIGHT,
        "closed_end": False,
        "doors": [
            {"leg": 0, "side": "right", "centre_m": 7.0, "width_m": 0.9, "recess_m": 0.12},
            {"leg": 0, "side": "left", "centre_m": 9.5, "width_m": 1.0, "recess_m": 0.1},
            {"leg": 0, "side": "left", "centre_m": 17.5, "width_m": 0.9, "recess_m": 0.15},
            {"leg": 1, "side": "right", "centre_m": 3.5, "width_m": 0.9, "recess_m": 0.12},
            {"leg": 1, "side": "left", "centre_m": 11.5, "width_m": 1.2, "recess_m": 0.08},
        ],
        "doorways": [
            {"leg": 0, "side": "left", "centre_m": 4.5, "width_m": 1.2, "height_m": 2.2,
             "wall_thickness_m": 0.12,
             "room": {"width_m": 5.0, "depth_m": 4.2, "height_m": 2.8}},
            {"leg": 0, "side": "right", "centre_m": 13.5, "width_m": 1.1, "height_m": 2.1,
             "wall_thickness_m": 0.12,
             "room": {"width_m": 4.0, "depth_m": 3.6, "height_m": 2.7, "offset_m": -0.3}},
            {"leg": 1, "side": "left", "centre_m": 7.0, "width_m": 1.2, "height_m": 2.2,
             "wall_thickness_m": 0.12,
             "room": {"width_m": 4.0, "depth_m": 4.0, "height_m": 2.8}},
        ],
    }],
    "clutter": clutter,
    "rectangles": [end_wall],
    "path": {
        "waypoints": [at(0, 1.0, 0.0), at(0, LEGS[0], 0.0), at(1, 13.0, 0.0)],
        "speed_m_s": 0.4,
        "corner_radius_m": 1.0,
    },
    "noise": {
        "range_sigma_m": 0.02,
        "range_sigma_per_m": 0.002,
        "incidence_noise_factor": 0.5,
        "grazing_dropout_deg": 85.0,
        "dropout_probability": 0.02,
        "spurious_probability": 0.005,
        "mixed_pixel_probability": 0.5,
        "mixed_pixel_jump_m": 0.3,
    },
}

out = sys.argv[1] if len(sys.argv) > 1 else "config/worlds/cluttered.json"
with open(out, "w") as f:
    json.dump(world, f, indent=2)
    f.write("\n")
print(out)
