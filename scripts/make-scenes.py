#!/usr/bin/env python3
"""Generates the built-in contact scenes with many bodies in assets/scenes/.

    scripts/make-scenes.py      # rewrites every scene below; review `git diff` before committing

bouncing_balls   ten balls dropped side by side, restitution 0, 0.1, ..., 0.9
dominoes         a curved row of dominoes, the first one pushed
tower_ball       a tower of crossed bars knocked over by a heavy ball
newtons_cradle   five steel balls on a frictionless track between two elastic end walls
sphere_rain      issue 4's benchmark scene, n = 10 (1000 spheres), columns shifted by its hash
sphere_columns   the same with the shift set to zero: a column-stacking test
spheres1000      1000 floating, spinning spheres that never touch: the render benchmark's scene
                 of many bodies (bench/render/render_bench.cpp), written to bench/scenes/, not
                 built in
The hand-written scenes (default, spinning_top, tossed_book) are not generated.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "assets", "scenes")
DT = 1.0 / 240.0


def r6(x):
    return round(x, 6)


def write(name, scene, out=OUT):
    path = os.path.join(out, name + ".json")
    bodies = scene.pop("bodies")
    text = json.dumps(scene, indent=2)[:-2]  # drop the closing "\n}"
    text += ',\n  "bodies": [\n' + ",\n".join("    " + json.dumps(b) for b in bodies) + "\n  ]\n}\n"
    with open(path, "w") as f:
        f.write(text)
    print("wrote", os.path.relpath(path), len(bodies), "bodies")


def ground(extent=30, color="#d2d0c8", friction=0.5):
    return {"name": "ground", "shape": {"type": "plane", "extent": extent}, "color": color,
            "material": {"preset": "matte", "friction": friction}}


def hsv(h, s=0.65, v=0.9):
    i = int(h * 6) % 6
    f = h * 6 - int(h * 6)
    p, q, t = v * (1 - s), v * (1 - s * f), v * (1 - s * (1 - f))
    rgb = [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)][i]
    return "#%02x%02x%02x" % tuple(int(round(255 * c)) for c in rgb)


def bouncing_balls():
    balls = []
    for k in range(10):
        e = k / 10
        balls.append({"name": "e = %.1f" % e, "shape": {"type": "sphere", "radius": 0.1},
                      "density": 400, "position": [r6(-1.35 + 0.3 * k), 0, 1.6],
                      "color": hsv(0.6 - 0.6 * k / 9), "material": {"preset": "rubber",
                                                                      "friction": 0.6,
                                                                      "restitution": e}})
    return {"format_version": 1,
            "title": "Ten balls dropped from 1.5 m with restitution 0, 0.1, ..., 0.9 (left to right)",
            "world": {"dt": DT, "duration": 8},
            "render": {"camera": {"position": [0, -3.1, 0.9], "target": [0, 0, 0.75],
                                  "fov_deg": 45},
                       "light": {"direction": [-0.3, 0.5, -1], "ambient": 0.3}},
            "bodies": [ground(friction=0.6)] + balls}


def dominoes():
    bodies = [ground()]
    n, radius, arc = 28, 1.6, math.radians(200)
    size = [0.03, 0.13, 0.26]  # thin along the row, wide across it, tall
    for k in range(n):
        a = -0.5 * arc + arc * k / (n - 1)  # along a circle about the origin
        x, y = radius * math.sin(a), -radius * math.cos(a) + 0.6
        # Body x along the row (the circle's tangent): rotate about z by a.
        d = {"name": "domino %d" % k, "shape": {"type": "box", "size": size}, "density": 650,
             "position": [r6(x), r6(y), 0.13], "orientation": {"axis": [0, 0, 1],
                                                               "angle_rad": r6(a)},
             "color": hsv(k / n, 0.55, 0.92), "material": {"preset": "glossy", "friction": 0.4}}
        if k == 0:  # a push: it starts tipping about its front bottom edge at w rad/s
            w, half = 3.0, [0.5 * s for s in size]
            # v = w x (centre - edge) = (w h, 0, w t) in body axes (t, h: half thickness,
            # height), turned into the world by the domino's angle a.
            v = [w * half[2], 0.0, w * half[0]]
            d["velocity"] = [r6(v[0] * math.cos(a)), r6(v[0] * math.sin(a)), r6(v[2])]
            d["angular_velocity"] = [0, w, 0]
            d["angular_velocity_frame"] = "body"
        bodies.append(d)
    return {"format_version": 1, "title": "Twenty-eight dominoes on an arc; the first is pushed",
            "world": {"dt": DT, "duration": 5},
            "render": {"camera": {"position": [0.5, -3.0, 1.5], "target": [0, 0.35, 0.05],
                                  "fov_deg": 50}},
            "bodies": bodies}


def tower_ball():
    bodies = [ground()]
    bar, layers = [0.6, 0.18, 0.14], 9
    for layer in range(layers):
        z = 0.07 + 0.14 * layer
        for side in (-1, 1):
            along_x = layer % 2 == 0
            pos = [0, side * 0.21, z] if along_x else [side * 0.21, 0, z]
            b = {"name": "bar %d%s" % (layer, "ab"[side > 0]), "shape": {"type": "box",
                                                                         "size": bar},
                 "density": 500, "position": [r6(p) for p in pos],
                 "color": "#c8894b" if layer % 2 else "#e0a862",
                 "material": {"preset": "matte", "friction": 0.6}}
            if not along_x:
                b["orientation"] = {"axis": [0, 0, 1], "angle_deg": 90}
            bodies.append(b)
    # A heavy ball thrown from 4.5 m away: it meets the tower after 0.58 s at z ~ 0.8 m.
    bodies.append({"name": "ball", "shape": {"type": "sphere", "radius": 0.16}, "density": 3000,
                   "position": [-4.5, 0.05, 1.3], "velocity": [7.0, 0, 2.0],
                   "color": "#2e6fba", "material": {"preset": "metal", "friction": 0.4,
                                                   "restitution": 0.2}})
    return {"format_version": 1, "title": "A tower of crossed bars knocked over by a heavy ball",
            "world": {"dt": DT, "duration": 6},
            "render": {"camera": {"position": [0.2, -5.2, 1.9], "target": [-1.0, 0, 0.6],
                                  "fov_deg": 45}},
            "bodies": bodies}


def newtons_cradle():
    r, steel = 0.1, {"preset": "metal", "friction": 0.0, "restitution": 1.0}
    bodies = [ground(friction=0.0)]
    for side in (-1, 1):  # elastic end walls, 1 m either side of the row's centre
        bodies.append({"name": "wall %s" % ("left" if side < 0 else "right"),
                       "shape": {"type": "box", "size": [0.1, 0.6, 0.3]}, "static": True,
                       "position": [side * 1.05, 0, 0.15], "color": "#6b4f3a",
                       "material": {"preset": "matte", "friction": 0.0, "restitution": 1.0}})
    for k in range(5):
        b = {"name": "ball %d" % (k + 1), "shape": {"type": "sphere", "radius": r},
             "density": 7800, "position": [r6(-0.4 + 2 * r * k), 0, r], "color": "#c9ccd1",
             "material": steel}
        if k == 0:
            b["position"][0] = -0.8
            b["velocity"] = [1.2, 0, 0]
        bodies.append(b)
    return {"format_version": 1,
            "title": "Newton's cradle on a frictionless track between two elastic walls",
            "world": {"dt": DT, "duration": 8, "sleeping": False},
            "render": {"camera": {"position": [0.2, -1.8, 0.6], "target": [0, 0, 0.12],
                                  "fov_deg": 45}},
            "bodies": bodies}


def rain_hash(i, k):
    """Issue 4's 32-bit hash, u(i, k) in [-1, 1) (physics/scenes/sphere_rain.cpp has the same)."""
    m = 0xFFFFFFFF
    h = (i * 2654435761 + k * 0x9E3779B9) & m
    h ^= h >> 16
    h = (h * 0x85EBCA6B) & m
    h ^= h >> 13
    h = (h * 0xC2B2AE35) & m
    h ^= h >> 16
    return h / 4294967296.0 * 2.0 - 1.0


def sphere_rain(shifted, n=10):
    """Issue 4's benchmark scene; physics/scenes/sphere_rain.cpp builds it too (a test compares)."""
    bodies = [{"name": "floor", "shape": {"type": "plane", "extent": 14}, "color": "#d2d0c8",
               "material": {"preset": "matte", "friction": 0.5}}]
    t = 0.05  # half thickness of a wall; inner faces on x, y = +-2
    wall = {"static": True, "color": "#8a9bb0", "material": {"preset": "matte", "friction": 0.5}}
    for side in (-1, 1):
        bodies.append(dict(wall, name="wall x%+d" % side,
                           shape={"type": "box", "size": [2 * t, 4 + 4 * t, 1]},
                           position=[side * (2 + t), 0, 0.5]))
    for side in (-1, 1):
        bodies.append(dict(wall, name="wall y%+d" % side,
                           shape={"type": "box", "size": [4, 2 * t, 1]},
                           position=[0, side * (2 + t), 0.5]))
    spacing, centre = 0.12, 0.5 * (n - 1) * 0.12
    for i in range(n ** 3):
        ix, iy, iz = i % n, (i // n) % n, i // (n * n)
        dx = 0.01 * rain_hash(i, 0) if shifted else 0.0
        dy = 0.01 * rain_hash(i, 1) if shifted else 0.0
        # repr() of a float round-trips exactly, so the scene is bit for bit the C++ builder's.
        pos = [ix * spacing - centre + dx, iy * spacing - centre + dy, 0.5 + iz * spacing]
        bodies.append({"name": "s%d" % i, "shape": {"type": "sphere", "radius": 0.05},
                       "mass": 0.1, "position": pos, "color": hsv(iz / n, 0.6, 0.9),
                       "material": {"friction": 0.5, "restitution": 0.3}})
    what = "columns shifted by the issue's hash" if shifted else "no shift: a column-stacking test"
    return {"format_version": 1,
            "title": "Sphere rain: %d spheres into a 4 m box, %s" % (n ** 3, what),
            "world": {"dt": DT, "duration": 5, "sleeping": False},
            "render": {"camera": {"position": [3.2, -4.4, 3.4], "target": [0, 0, 0.4],
                                  "fov_deg": 45}},
            "bodies": bodies}


def spheres1000():
    """1000 spheres in a 10 x 10 x 10 lattice above a ground, floating (gravity_scale 0) and each
    spinning about its own axis, drifting together so nothing ever touches. The camera orbits."""
    colours = ["#c0392b", "#2e86c1", "#f1c40f", "#27ae60", "#8e44ad", "#e67e22"]
    g = lambda x: float(format(x, "g"))  # 6 significant digits, as the scene always had
    bodies = [{"name": "ground", "shape": {"type": "plane", "extent": 40},
               "color": [0.82, 0.82, 0.8]}]
    for i in range(1000):
        a, b, c = i % 10, (i // 10) % 10, i // 100
        bodies.append({"shape": {"type": "sphere", "radius": 0.17}, "gravity_scale": 0,
                       "position": [g(-2.7 + 0.6 * a), g(-2.7 + 0.6 * b), g(0.5 + 0.45 * c)],
                       "velocity": [0, 0, 0.02],
                       "angular_velocity": [g(0.3 * (a - 5)), g(0.2 * (b - 5)), 1.5],
                       "color": colours[(a + b + c) % 6]})
    return {"format_version": 1, "title": "1000 spheres (benchmark)",
            "world": {"duration": 10},
            "render": {"camera": {"position": [9, -12, 7], "target": [0, 0, 2.4], "fov_deg": 45,
                                  "orbit": {"period": 40}},
                       "light": {"direction": [-0.5, 0.4, -1.0], "ambient": 0.3}},
            "bodies": bodies}


def main():
    write("bouncing_balls", bouncing_balls())
    write("dominoes", dominoes())
    write("tower_ball", tower_ball())
    write("newtons_cradle", newtons_cradle())
    write("sphere_rain", sphere_rain(True))
    write("sphere_columns", sphere_rain(False))
    write("spheres1000", spheres1000(), os.path.join(HERE, "..", "bench", "scenes"))


if __name__ == "__main__":
    main()
