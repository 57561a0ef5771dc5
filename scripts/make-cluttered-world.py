#!/usr/bin/env python3
"""Writes issue 16's cluttered worlds (doc/real-geometry.md), laid out in each
corridor leg's own coordinates (s along it, d to its left) and turned into
world coordinates here, so the files stay readable as numbers:

- config/worlds/cluttered.json: an L-shaped office corridor turned 23 degrees
  off the axes, with furniture, ceiling clutter (lamps, a duct, a beam across,
  a pipe), rooms with desks and shelves seen through open doorways, a slanted
  end wall, and the laser errors of real sensors (doc/simulator.md, "Laser
  errors");
- config/worlds/glass-office.json: a U-shaped corridor turned -37 degrees,
  two rooms behind glass fronts, people walking along the corridor, other
  furniture and ceiling clutter, a slanted end wall, the same laser errors
  plus glass (doc/simulator.md, "Glass", "People").

Usage: scripts/make-cluttered-world.py [OUT_DIR]   (default config/worlds)
"""
import json
import math
import os
import sys


def r3(v):
    return round(v, 6)


class Legs:
    """A corridor's legs: starting at `start`, heading `heading_deg`, each leg
    turning by +-90 degrees (`turns`: +1 left, -1 right) from the one before."""

    def __init__(self, heading_deg, lengths, turns, start=(0.0, 0.0)):
        h = math.radians(heading_deg)
        d = (math.cos(h), math.sin(h))
        self.dirs = [d]
        for t in turns:
            d = (-t * d[1], t * d[0])
            self.dirs.append(d)
        self.starts = [start]
        for length, d in zip(lengths, self.dirs):
            o = self.starts[-1]
            self.starts.append((o[0] + length * d[0], o[1] + length * d[1]))
        self.lengths = lengths

    def centreline(self):
        return [[r3(p[0]), r3(p[1])] for p in self.starts]

    def at(self, leg, s, d):
        """World [x, y] of the point s along leg `leg` and d to its left."""
        o, t = self.starts[leg], self.dirs[leg]
        n = (-t[1], t[0])
        return [r3(o[0] + s * t[0] + d * n[0]), r3(o[1] + s * t[1] + d * n[1])]

    def yaw(self, leg):
        return r3(math.degrees(math.atan2(self.dirs[leg][1], self.dirs[leg][0])))

    def box(self, kind, leg, s, d, along, across, z0, z1):
        return {"kind": kind, "shape": "box", "centre": self.at(leg, s, d),
                "size_m": [along, across], "yaw_deg": self.yaw(leg), "z_min_m": z0,
                "z_max_m": z1}

    def cylinder(self, kind, leg, s, d, r, z0, z1):
        return {"kind": kind, "shape": "cylinder", "centre": self.at(leg, s, d),
                "radius_m": r, "z_min_m": z0, "z_max_m": z1}

    def upright(self, kind, a, b, z0, z1, towards):
        """A vertical rectangle from [x, y] a to b, z0 to z1, facing the leg
        point `towards` = (leg, s, d) (corners counter-clockwise from there)."""
        rect = {"kind": kind, "corners": [a + [z0], a + [z1], b + [z1], b + [z0]]}
        c0, c1, c3 = rect["corners"][0], rect["corners"][1], rect["corners"][3]
        e1 = [c1[i] - c0[i] for i in range(3)]
        e3 = [c3[i] - c0[i] for i in range(3)]
        normal = (e1[1] * e3[2] - e1[2] * e3[1], e1[2] * e3[0] - e1[0] * e3[2])
        p = self.at(*towards)
        if normal[0] * (p[0] - a[0]) + normal[1] * (p[1] - a[1]) < 0:
            rect["corners"] = [b + [z0], b + [z1], a + [z1], a + [z0]]
        return rect


def slanted_end_wall(legs, leg, end_s, width, height, degrees):
    """A wall across `leg` at `end_s`, `degrees` off square, facing back along the leg."""
    slant = math.tan(math.radians(degrees))
    half = 0.5 * width
    a = legs.at(leg, end_s - half * slant, -half)
    b = legs.at(leg, end_s + half * slant, half)
    return legs.upright("wall", a, b, 0.0, height, (leg, end_s - 2.0, 0.0))


LASER_ERRORS = {
    "range_sigma_m": 0.02,
    "range_sigma_per_m": 0.002,
    "incidence_noise_factor": 0.5,
    "grazing_dropout_deg": 85.0,
    "dropout_probability": 0.02,
    "spurious_probability": 0.005,
    "mixed_pixel_probability": 0.5,
    "mixed_pixel_jump_m": 0.3,
}


def cluttered():
    HEIGHT = 2.8
    WIDTH = 2.4
    LEGS = [20.0, 16.5]  # the second leg runs on past the slanted end wall
    L = Legs(23.0, LEGS, [-1])  # a right turn
    box, cylinder, at = L.box, L.cylinder, L.at
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

    # The slanted end wall across leg 1, 30 degrees off square, facing the robot.
    end_wall = slanted_end_wall(L, 1, 15.5, WIDTH, HEIGHT, 30.0)

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
            "centreline": L.centreline(),
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
        "noise": dict(LASER_ERRORS),
    }
    return world


def glass_office():
    HEIGHT = 2.6
    WIDTH = 2.2
    LEGS = [16.0, 9.0, 15.0]
    L = Legs(-37.0, LEGS, [1, 1])  # two left turns: a U
    box, cylinder, at = L.box, L.cylinder, L.at
    half = 0.5 * WIDTH
    clutter = [
        # leg 0: the right wall (people walk along the left lane)
        box("radiator", 0, 2.5, -1.04, 1.2, 0.12, 0.15, 0.7),
        box("cabinet", 0, 11.0, -0.85, 1.0, 0.5, 0.0, 1.9),
        cylinder("bin", 0, 14.0, -0.85, 0.18, 0.0, 0.7),
        box("pipe", 0, 8.0, 0.95, 14.0, 0.08, 2.3, 2.38),
        # the glass meeting room on the left of leg 0, and the one on the right of leg 2
        box("desk", 0, 6.0, 3.3, 2.4, 1.0, 0.0, 0.74),
        box("shelf", 0, 4.4, 4.65, 1.2, 0.4, 0.0, 1.8),
        box("desk", 2, 3.5, -2.9, 1.4, 0.7, 0.0, 0.74),
        box("cabinet", 2, 4.8, -3.8, 0.8, 0.5, 0.0, 1.1),
        # leg 1: a printer, a water cooler, a column
        box("cabinet", 1, 3.0, 0.8, 0.6, 0.5, 0.0, 1.1),
        cylinder("bin", 1, 5.0, 0.85, 0.16, 0.0, 1.3),
        cylinder("column", 1, 7.0, -0.9, 0.2, 0.0, HEIGHT),
        box("beam", 1, 4.5, 0.0, 0.3, WIDTH, 2.3, HEIGHT),
        # leg 2: shelves and a bench along the left wall (people use the right lane)
        box("shelf", 2, 3.0, 0.9, 1.4, 0.35, 0.0, 2.0),
        box("desk", 2, 6.5, 0.85, 1.6, 0.45, 0.0, 0.45),
        cylinder("bin", 2, 12.5, 0.85, 0.2, 0.0, 0.8),
        box("duct", 2, 7.5, -0.7, 12.0, 0.5, 2.2, 2.5),
    ]
    for s in (2.0, 5.0, 8.0, 11.0, 14.0):
        clutter.append(box("lamp", 0, s, 0.0, 0.6, 0.6, 2.54, 2.6))
    for s in (2.0, 7.0):
        clutter.append(box("lamp", 1, s, 0.0, 0.6, 0.6, 2.54, 2.6))
    for s in (2.0, 5.0, 11.0):
        clutter.append(box("lamp", 2, s, 0.3, 0.6, 0.6, 2.54, 2.6))

    # Glass fronts across two wide doorways, in the middle of the wall's thickness.
    wall = 0.1
    fronts = [(0, 6.0, 4.0, 1), (2, 3.5, 3.0, -1)]  # leg, centre, width, side (+1 left)
    glass = []
    for leg, c, w, side in fronts:
        d = side * (half + 0.5 * wall)
        glass.append(L.upright("glass", at(leg, c - 0.5 * w, d), at(leg, c + 0.5 * w, d), 0.0,
                               2.3, (leg, c, 0.0)))
    end_wall = slanted_end_wall(L, 2, 14.5, WIDTH, HEIGHT, 20.0)

    return {
        "name": "glass-office",
        "description": (
            "U-shaped office corridor (legs 16, 9 and 15 m, 2.2 m wide, 2.6 m high) turned -37 "
            "degrees off the axes, with two meeting rooms behind glass fronts (4 m and 3 m "
            "wide; the lasers see through the glass except within glass_return_deg of its "
            "normal), two people walking to and fro along the corridor, two doors, furniture "
            "(radiator, cabinets, bins, shelves, a bench, a column), ceiling clutter (lamps, "
            "a beam across, a duct, a pipe), a slanted end wall 20 degrees off square and the "
            "laser errors of real sensors. Issue 16's second cluttered world; written by "
            "scripts/make-cluttered-world.py."),
        "corridors": [{
            "name": "U",
            "centreline": L.centreline(),
            "width_m": WIDTH,
            "height_m": HEIGHT,
            "closed_end": False,
            "doors": [
                {"leg": 0, "side": "right", "centre_m": 7.0, "width_m": 0.9, "recess_m": 0.1},
                {"leg": 2, "side": "left", "centre_m": 10.0, "width_m": 1.0, "recess_m": 0.12},
            ],
            "doorways": [
                {"leg": leg, "side": "left" if side > 0 else "right", "centre_m": c,
                 "width_m": w, "height_m": 2.3, "wall_thickness_m": wall,
                 "room": {"width_m": w + 1.0, "depth_m": 3.5, "height_m": HEIGHT}}
                for leg, c, w, side in fronts
            ],
        }],
        "clutter": clutter,
        "rectangles": glass + [end_wall],
        "people": [
            {"waypoints": [at(0, 2.0, 0.55), at(0, 13.5, 0.55)], "speed_m_s": 1.1,
             "start_s": 4.0},
            {"waypoints": [at(2, 2.0, -0.55), at(2, 12.0, -0.55)], "speed_m_s": 1.3,
             "start_s": 0.0},
        ],
        "path": {
            "waypoints": [at(0, 1.0, 0.0), at(0, LEGS[0], 0.0), at(1, LEGS[1], 0.0),
                          at(2, 12.5, 0.0)],
            "speed_m_s": 0.4,
            "corner_radius_m": 1.0,
        },
        "noise": dict(LASER_ERRORS, glass_return_deg=10.0, glass_dropout_probability=0.3),
    }


out_dir = sys.argv[1] if len(sys.argv) > 1 else "config/worlds"
for name, world in (("cluttered", cluttered()), ("glass-office", glass_office())):
    out = os.path.join(out_dir, name + ".json")
    with open(out, "w") as f:
        json.dump(world, f, indent=2)
        f.write("\n")
    print(out)
