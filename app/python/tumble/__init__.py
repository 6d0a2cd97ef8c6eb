"""Tumble from Python: rigid bodies stepped by Tumble's physics core and drawn headlessly, with
NumPy arrays in and out (MuJoCo's way: arrays, not objects).

    import tumble
    scene = tumble.load("default")          # a built-in name, a file path, or a dict
    traj = tumble.simulate(scene)           # traj.t, traj.position, traj.energy, ...
    frames = tumble.render(scene, frames=[0, 60, 120], width=640, height=360)
    video = tumble.render(scene, output="flip.mp4")   # shows inline in Jupyter
    sim = tumble.Simulation(scene); sim.step(240); sim.position

Every call prepares its run as the command line does (app/run/prepare_run.h), so a scene gives
the same bits here as from `tumble`: simulate's arrays are the numbers `tumble simulate` writes,
and frame k is the picture `tumble render --frame k` draws. Keywords mean what the command
line's options mean and are refused with their messages (tumble.BadInput, a ValueError); a run
that fails otherwise raises tumble.RunFailed. Long calls release the GIL and stop on Ctrl-C
(KeyboardInterrupt) within a frame or a step. docs/python.md has the whole of it.
"""
from __future__ import annotations

import os
from typing import Iterable, Optional, Sequence, Tuple, Union

import numpy as np

from . import _tumble
from ._output import Output
from ._tumble import (BadInput, RunFailed, Scene, Trajectory, TumbleWarning, __version__,
                      integrators, scenes)

__all__ = ["BadInput", "RunFailed", "TumbleWarning", "Scene", "Trajectory", "Simulation",
           "Output", "load", "simulate", "render", "scenes", "integrators", "__version__"]

SceneLike = Union[Scene, str, "os.PathLike[str]", dict]
Tolerance = Union[float, Tuple[float, float], str]
ErrorEstimate = Union[bool, Sequence[float], str]


def load(scene: SceneLike) -> Scene:
    """Loads and checks a scene: a built-in scene's name ("default", "lessons/intermediate_axis";
    tumble.scenes() lists them), a scene file's path, or a dict in the scene format
    (docs/scene-format.md). Its warnings become TumbleWarning; a bad scene raises BadInput naming
    the file and the JSON path or line:column. A Scene is returned as it is."""
    if isinstance(scene, Scene):
        return scene
    return _tumble._load(scene)


def _run(integrator, tolerance, duration, dt, error_estimate) -> dict:
    return {"integrator": integrator, "tolerance": tolerance, "duration": duration, "dt": dt,
            "error_estimate": error_estimate}


def _in_range(option: str, value, low, high=None) -> None:
    """The command line's range checks (its parser's), with the option's name."""
    if value is None:
        return
    if value < low or (high is not None and value > high):
        expected = "at least %s" % low if high is None else "%s to %s" % (low, high)
        raise BadInput("%s %s: expected %s" % (option, value, expected))


def _names(value) -> Optional[list]:
    """A list of names, or one string of names separated by commas (as the command line)."""
    if value is None or isinstance(value, list):
        return value
    if isinstance(value, str):
        return value.split(",")
    return list(value)


def _body(value) -> Optional[str]:
    """A body named or counted (the command line takes either as text)."""
    return None if value is None else str(value)


def simulate(scene: SceneLike, *, integrator: Optional[str] = None, dt: Optional[float] = None,
             duration: Optional[float] = None, tolerance: Optional[Tolerance] = None,
             error_estimate: Optional[ErrorEstimate] = None, every: int = 1,
             fps: Optional[int] = None, threads: int = 1) -> Trajectory:
    """Steps the scene from t = 0 to its duration without drawing: `tumble simulate`.

    Returns a Trajectory with one row at t = 0, every `every`-th step and the last step:
    t (T,), position (T, B, 3), orientation (T, B, 4: w, x, y, z), velocity and angular_velocity
    (T, B, 3) of the B moving bodies (traj.bodies), and energy, kinetic, potential (T,),
    momentum and angular_momentum (T, 3). traj.write_csv(path) writes the command line's CSV.

    integrator: a name (tumble.integrators()) or "auto" (needs a tolerance); dt, duration: the
    scene's step and duration overridden, s; tolerance: R or (R, P), the largest error each body
    may reach over the run, rad and m (picks the cheapest integrator and step that meet it, or
    checks the named one: docs/accuracy.md); error_estimate: True, False, or times in s at which
    to keep it (traj.error_rotation, traj.error_position); fps: the frame times the step lands
    on (render's); threads: physics threads for contacts (the same bits for any count).
    """
    _in_range("--threads", threads, 1, 64)
    _in_range("--fps", fps, 1, 1000)
    return _tumble._simulate(load(scene), _run(integrator, tolerance, duration, dt,
                                               error_estimate),
                             every, fps, threads, False)


class Simulation(_tumble._Simulation):
    """A scene made ready to step by hand, as tumble.simulate and `tumble simulate` step it:

        sim = tumble.Simulation("default")
        sim.step(240)              # 240 steps of sim.dt
        sim.t, sim.position        # 1.0 s; (B, 3) metres

    After k steps it holds row k of tumble.simulate's trajectory, bit for bit. The keywords are
    simulate's. Properties: t, steps, dt, steps_per_frame, integrator, bodies, position,
    orientation, velocity, angular_velocity ((B, 3) or (B, 4) arrays, fresh copies), energy,
    kinetic, potential, momentum, angular_momentum, notes, summary.
    """

    def __init__(self, scene: SceneLike, *, integrator: Optional[str] = None,
                 dt: Optional[float] = None, duration: Optional[float] = None,
                 tolerance: Optional[Tolerance] = None,
                 error_estimate: Optional[ErrorEstimate] = None, fps: Optional[int] = None,
                 threads: int = 1) -> None:
        _in_range("--threads", threads, 1, 64)
        _in_range("--fps", fps, 1, 1000)
        super().__init__(load(scene), _run(integrator, tolerance, duration, dt, error_estimate),
                         fps, threads)


def render(scene: SceneLike, frames: Optional[Iterable[int]] = None, *,
           output: Optional[Union[str, "os.PathLike[str]"]] = None, frame: Optional[int] = None,
           time: Optional[float] = None, width: Optional[int] = None,
           height: Optional[int] = None, fps: Optional[int] = None, preview: bool = False,
           shadows: Optional[bool] = None, soft_shadows: Optional[bool] = None,
           ambient_occlusion: Optional[bool] = None, reflections: Optional[bool] = None,
           antialiasing: Optional[bool] = None, overlay: Optional[bool] = None,
           axes: Optional[bool] = None, vectors: Optional[bool] = None,
           chart: Optional[Union[str, Sequence[str]]] = None,
           chart_body: Optional[Union[str, int]] = None, chart_window: Optional[float] = None,
           trails: Optional[bool] = None, trail_seconds: Optional[float] = None,
           trail_axis: Optional[str] = None, poinsot: Optional[Union[str, int]] = None,
           overlay_body: Optional[Union[str, int]] = None,
           compare: Optional[Union[str, Sequence[str]]] = None, crf: int = 18,
           preset: Optional[str] = None, overwrite: bool = False,
           integrator: Optional[str] = None, dt: Optional[float] = None,
           duration: Optional[float] = None, tolerance: Optional[Tolerance] = None,
           error_estimate: Optional[ErrorEstimate] = None, threads: int = 1,
           progress: bool = False) -> Union[np.ndarray, Output]:
    """Draws the scene: `tumble render`.

    Without `output`: the frames as one uint8 array (F, H, W, 3), rows top-down, RGB; `frames`
    picks frame indices (frame k shows t = k / fps; any order, repeats allowed; default every
    frame of the run, which at 1280x720 is 2.7 MB a frame), `frame` (or `time`, s: the nearest
    frame) one frame as (H, W, 3). Frame k is the picture `tumble render --frame k` draws.

    With `output`: what `tumble render -o OUTPUT` writes (out.mp4, out.webm, out.gif, frames/,
    frames/%06d.png, still.png with frame= or time=, or null), returned as an Output that shows
    inline in Jupyter. compare=["euler", "rk4"] draws integrators side by side (an output only).

    The picture keywords are the command line's switches (--width, --height, --fps, --preview,
    --[no-]shadows, --[no-]soft-shadows, --[no-]ao as ambient_occlusion, --[no-]reflections,
    --[no-]aa as antialiasing, --[no-]overlay, --[no-]axes, --[no-]vectors, --chart,
    --chart-body, --chart-window, --[no-]trails, --trail-seconds, --trail-axis, --poinsot,
    --overlay-body, --crf, --preset, --overwrite); None keeps the scene's setting. integrator,
    dt, duration, tolerance, error_estimate and threads are simulate's. progress: a progress bar
    on a terminal's standard error.
    """
    _in_range("--threads", threads, 1, 64)
    _in_range("--crf", crf, 0, 63)
    _in_range("--chart-window", chart_window, 0)
    if trail_seconds is not None and not trail_seconds > 0:
        raise BadInput("--trail-seconds %s: expected a positive number of seconds"
                       % trail_seconds)
    picture = {
        "output": None if output is None else os.fspath(output), "frame": frame, "time": time,
        "width": width, "height": height, "fps": fps, "preview": preview, "shadows": shadows,
        "soft_shadows": soft_shadows, "ambient_occlusion": ambient_occlusion,
        "reflections": reflections, "antialiasing": antialiasing, "overlay": overlay,
        "axes": axes, "vectors": vectors, "chart": _names(chart), "chart_body": _body(chart_body),
        "chart_window": chart_window, "trails": trails, "trail_seconds": trail_seconds,
        "trail_axis": trail_axis, "poinsot": _body(poinsot),
        "overlay_body": _body(overlay_body), "compare": _names(compare), "crf": crf,
        "preset": preset, "overwrite": overwrite,
    }
    run = _run(integrator, tolerance, duration, dt, error_estimate)
    if output is None:
        if frames is not None and not isinstance(frames, (list, tuple)):
            frames = list(np.asarray(frames).reshape(-1).tolist())
        return _tumble._render_frames(load(scene), frames, run, picture, threads, progress)
    if frames is not None:
        raise BadInput("frames= draws into an array and output= into a file: give one "
                       "(frame= or time= for one still in the file)")
    result = _tumble._render_output(load(scene), run, picture, threads, progress)
    return Output(result["output"], result["frames"], result["notes"], result["diverged"])
