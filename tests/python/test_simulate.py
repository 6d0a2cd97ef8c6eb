"""tumble.simulate and tumble.Simulation: the same run as `tumble simulate` (the CSV's numbers,
bit for bit, and its files byte for byte), checked against exact solutions of the physics."""
import os

import numpy as np
import pytest

import support
import tumble


def test_arrays_are_the_numbers_tumble_simulate_writes():
    out = support.scratch("simulate_csv")
    cli = os.path.join(out, "cli.csv")
    support.tumble("simulate", "default", "--duration", "1.5", "--every", "3", "-q", "-o", cli)
    traj = tumble.simulate("default", duration=1.5, every=3)

    states = support.read_states(cli)
    moving = traj.bodies
    rows = [i for i, name in enumerate(states["name"]) if name in moving]
    T, B = len(traj), len(moving)
    assert traj.position.shape == (T, B, 3) and traj.orientation.shape == (T, B, 4)
    assert len(rows) == T * B

    def cli_array(cols):
        return np.stack([states[c][rows] for c in cols], axis=-1).reshape(T, B, len(cols))

    np.testing.assert_array_equal(traj.t, states["t"][rows].reshape(T, B)[:, 0])
    np.testing.assert_array_equal(traj.position, cli_array(["x", "y", "z"]))
    np.testing.assert_array_equal(traj.orientation, cli_array(["qw", "qx", "qy", "qz"]))
    np.testing.assert_array_equal(traj.velocity, cli_array(["vx", "vy", "vz"]))
    np.testing.assert_array_equal(traj.angular_velocity, cli_array(["wx", "wy", "wz"]))
    diags = support.read_table(os.path.join(out, "cli.diagnostics.csv"))
    np.testing.assert_array_equal(traj.energy, diags["energy"])
    np.testing.assert_array_equal(traj.kinetic, diags["kinetic"])
    np.testing.assert_array_equal(traj.momentum, np.stack([diags[c] for c in "px py pz".split()], 1))
    np.testing.assert_array_equal(traj.angular_momentum,
                                  np.stack([diags[c] for c in "lx ly lz".split()], 1))


def test_write_csv_writes_the_command_lines_files_byte_for_byte():
    out = support.scratch("simulate_write_csv")
    cli, py = os.path.join(out, "cli.csv"), os.path.join(out, "py.csv")
    support.tumble("simulate", "lessons/intermediate_axis", "--duration", "2", "--every", "7",
                   "--error-estimate", "-q", "-o", cli)
    tumble.simulate("lessons/intermediate_axis", duration=2, every=7,
                    error_estimate=True).write_csv(py)
    for a, b in [(cli, py), (os.path.join(out, "cli.diagnostics.csv"),
                             os.path.join(out, "py.diagnostics.csv"))]:
        with open(a, "rb") as fa, open(b, "rb") as fb:
            assert fa.read() == fb.read(), (a, b)


def projectile(integrator):
    return {"format_version": 1,
            "world": {"gravity": [0, 0, -9.81], "dt": 1 / 240, "integrator": integrator,
                      "duration": 2},
            "bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "mass": 2,
                        "position": [0.5, -1, 10], "velocity": [1.5, 2, 7]}]}


@pytest.mark.parametrize("integrator", ["rk4", "splitting", "exact"])
def test_a_thrown_ball_follows_its_parabola(integrator):
    # x(t) = x0 + v0 t + g t^2 / 2, v(t) = v0 + g t: every integrator here is exact for a
    # constant force, so only round-off separates them.
    traj = tumble.simulate(projectile(integrator))
    t = traj.t[:, None]
    g = np.array([0, 0, -9.81])
    x0, v0 = np.array([0.5, -1, 10]), np.array([1.5, 2, 7])
    assert traj.t[-1] == pytest.approx(2.0, abs=1e-12)
    np.testing.assert_allclose(traj.position[:, 0], x0 + v0 * t + 0.5 * g * t**2, rtol=0,
                               atol=1e-11)
    np.testing.assert_allclose(traj.velocity[:, 0], v0 + g * t, rtol=0, atol=1e-11)
    # P = m v and E = m v^2 / 2 - m g.x, conserved by the exact motion.
    np.testing.assert_allclose(traj.momentum, 2 * (v0 + g * t), rtol=0, atol=1e-10)
    np.testing.assert_allclose(traj.energy, traj.energy[0], rtol=1e-12)


def rotate(axis, angle, v):
    """Rodrigues: v turned by `angle` about the unit `axis` (angles and vectors batched)."""
    k = axis / np.linalg.norm(axis)
    c, s = np.cos(angle)[:, None], np.sin(angle)[:, None]
    return v * c + np.cross(k, v) * s + k * (k @ v.T)[:, None] * (1 - c)


def test_a_torque_free_symmetric_top_precesses_as_the_closed_form_says():
    # A box with two equal sides (I1 = I2 = m (a^2 + c^2) / 12, I3 = m a^2 / 6), thrown
    # spinning with L not along its axis. Torque-free: L is constant in the world, the symmetry
    # axis e3 precesses about L at |L| / I1, and w = L / I1 + (1 / I3 - 1 / I1) (L . e3) e3
    # (Landau & Lifshitz, Mechanics, sec. 33).
    m, a, c = 3.0, 0.2, 0.5
    I1, I3 = m * (a * a + c * c) / 12, m * a * a / 6
    w0 = np.array([1.2, 0.0, 9.0])
    scene = {"format_version": 1,
             "world": {"gravity": [0, 0, 0], "dt": 1 / 600, "integrator": "exact",
                       "duration": 3},
             "bodies": [{"name": "top", "shape": {"type": "box", "size": [a, a, c]}, "mass": m,
                         "position": [0, 0, 0], "angular_velocity": w0.tolist()}]}
    traj = tumble.simulate(scene)
    L = np.array([I1 * w0[0], I1 * w0[1], I3 * w0[2]])
    t = traj.t
    e3 = rotate(L, np.linalg.norm(L) / I1 * t, np.array([[0.0, 0.0, 1.0]]))
    w = L / I1 + (1 / I3 - 1 / I1) * L[2] * e3
    np.testing.assert_allclose(traj.angular_velocity[:, 0], w, rtol=0, atol=1e-9)
    np.testing.assert_allclose(traj.angular_momentum, np.broadcast_to(L, (len(t), 3)), rtol=0,
                               atol=1e-12)


def test_simulation_stepped_by_hand_holds_simulates_rows():
    traj = tumble.simulate("default", duration=1)
    sim = tumble.Simulation("default", duration=1)
    assert sim.t == 0 and sim.bodies == traj.bodies
    sim.step(240)
    assert sim.steps == 240 and sim.t == traj.t[240]
    np.testing.assert_array_equal(sim.position, traj.position[240])
    np.testing.assert_array_equal(sim.orientation, traj.orientation[240])
    np.testing.assert_array_equal(sim.angular_velocity, traj.angular_velocity[240])
    assert sim.energy == traj.energy[240]


def test_bad_input_raises_badinput_with_the_command_lines_message():
    cli = support.tumble("simulate", "default", "--integrator", "nope", "-o",
                         os.path.join(support.scratch("bad_input"), "x.csv"), check=False)
    assert cli.returncode == 2
    with pytest.raises(tumble.BadInput) as e:
        tumble.simulate("default", integrator="nope")
    assert isinstance(e.value, ValueError)
    assert str(e.value) in cli.stderr
    with pytest.raises(tumble.BadInput, match="world.dt"):
        tumble.simulate({"format_version": 1, "world": {"dt": -1}, "bodies": []})
    with pytest.raises(tumble.BadInput):
        tumble.load("no/such/scene.json")
