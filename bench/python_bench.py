#!/usr/bin/python3
"""The Python module's costs against the command line's, measured in one run, interleaved
(issue 29's bounds; scripts/bench-python.sh runs it):

  simulate: `tumble simulate default -o FILE` (a process: loading its libraries, the scene, the
            10 s of stepping, the CSV) against, from Python, (a) tumble.simulate("default") in a
            warm interpreter (arrays only), (b) the same and write_csv(FILE) (the CLI's files),
            (c) a fresh /usr/bin/python3 doing import tumble, simulate and write_csv (the same
            work as the CLI's process, and the interpreter's and NumPy's start-up besides);
            bound: Python / CLI <= 1.1, checked on (b), the same output without a process.
  render:   tumble.render(scene, duration=D, width=W, height=H) into one NumPy array against
            `tumble render ... -o null` (the null sink: drawing without encoding), as frame
            rates; bound: Python fps / CLI fps >= 0.9.

Prints each repeat, the medians and the two ratios; appends them to a CSV with --csv.
usage: python_bench.py TUMBLE MODULE_DIR [--repeats N] [--csv FILE] [--machine NAME]
"""
import argparse
import datetime
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time


def wall(cmd):
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def timed(call):
    start = time.perf_counter()
    result = call()
    return time.perf_counter() - start, result


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tumble")
    ap.add_argument("module")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--duration", type=float, default=3.0, help="render case, s")
    ap.add_argument("--size", default="640x360", help="render case, WxH")
    ap.add_argument("--csv")
    ap.add_argument("--machine", default=socket.gethostname())
    args = ap.parse_args()
    sys.path.insert(0, args.module)
    import tumble

    width, height = map(int, args.size.split("x"))
    tmp = tempfile.mkdtemp(prefix="tumble-bench-python-")
    csv = os.path.join(tmp, "states.csv")
    sim_cli, sim_py, sim_csv, sim_fresh, fps_cli, fps_py = [], [], [], [], [], []
    pycsv = os.path.join(tmp, "py.csv")
    fresh = ["/usr/bin/python3", "-c", "import sys; sys.path.insert(0, %r); import tumble; "
             "tumble.simulate('default').write_csv(%r)" % (args.module, pycsv)]
    frames = round(args.duration * 60)
    render_cli = [args.tumble, "render", "default", "-q", "-o", "null", "--duration",
                  str(args.duration), "--width", str(width), "--height", str(height)]
    for r in range(args.repeats):
        sim_cli.append(wall([args.tumble, "simulate", "default", "-q", "-o", csv]))
        t, traj = timed(lambda: tumble.simulate("default"))
        sim_py.append(t)
        assert len(traj) == 2401, len(traj)
        del traj
        sim_csv.append(timed(lambda: tumble.simulate("default").write_csv(pycsv))[0])
        sim_fresh.append(wall(fresh))
        fps_cli.append(frames / wall(render_cli))
        t, array = timed(lambda: tumble.render("default", duration=args.duration, width=width,
                                               height=height))
        assert array.shape == (frames, height, width, 3), array.shape
        del array
        fps_py.append(frames / t)
        print("repeat %d: simulate cli %.3f s, python (a) %.3f s (b) %.3f s (c) %.3f s; render "
              "cli %.2f fps, python %.2f fps" % (r + 1, sim_cli[-1], sim_py[-1], sim_csv[-1],
                                                 sim_fresh[-1], fps_cli[-1], fps_py[-1]),
              flush=True)
    m = {k: statistics.median(v) for k, v in
         [("sim_cli", sim_cli), ("sim_py", sim_py), ("sim_csv", sim_csv),
          ("sim_fresh", sim_fresh), ("fps_cli", fps_cli), ("fps_py", fps_py)]}
    sim_ratio, fps_ratio = m["sim_csv"] / m["sim_cli"], m["fps_py"] / m["fps_cli"]
    load = os.getloadavg()[0]
    print("medians of %d: simulate default (10 s, 2400 steps): cli %.3f s; python (a) arrays "
          "%.3f s = %.3fx, (b) + write_csv %.3f s = %.3fx, (c) fresh interpreter %.3f s = %.3fx "
          "(bound <= 1.1 on b)" % (args.repeats, m["sim_cli"], m["sim_py"],
                                   m["sim_py"] / m["sim_cli"], m["sim_csv"], sim_ratio,
                                   m["sim_fresh"], m["sim_fresh"] / m["sim_cli"]))
    print("medians of %d: render default %gs %dx%d (%d frames): cli null sink %.2f fps, python "
          "NumPy %.2f fps, python/cli %.3f (bound >= 0.9)" % (args.repeats, args.duration, width,
                                                                height, frames, m["fps_cli"],
                                                                m["fps_py"], fps_ratio))
    print("load average (1 min) at the end: %.2f" % load)
    if args.csv:
        new = not os.path.exists(args.csv)
        with open(args.csv, "a") as f:
            if new:
                f.write("date,machine,load_1min,repeats,simulate_cli_s,simulate_python_s,"
                        "simulate_python_csv_s,simulate_python_fresh_s,simulate_ratio,render_size,render_frames,render_cli_null_fps,"
                        "render_python_fps,render_ratio\n")
            f.write("%s,%s,%.2f,%d,%.4f,%.4f,%.4f,%.4f,%.3f,%dx%d,%d,%.2f,%.2f,%.3f\n" % (
                datetime.datetime.now().isoformat(timespec="seconds"), args.machine, load,
                args.repeats, m["sim_cli"], m["sim_py"], m["sim_csv"], m["sim_fresh"], sim_ratio, width, height, frames,
                m["fps_cli"], m["fps_py"], fps_ratio))
    ok = sim_ratio <= 1.1 and fps_ratio >= 0.9
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
