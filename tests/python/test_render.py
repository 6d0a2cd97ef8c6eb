"""tumble.render: frames into NumPy equal the PNGs `tumble render --frame k` writes, and any
output the command line takes."""
import os

import numpy as np
import pytest

import support
import tumble

SMALL = {"width": 320, "height": 180}


def test_frames_are_the_pictures_of_tumble_render_frame_k():
    out = support.scratch("render_frames")
    frames = [0, 45, 90]
    # Out of order with a repeat: the array follows the order asked.
    asked = [90, 0, 45, 90]
    array = tumble.render("lessons/intermediate_axis", frames=asked, **SMALL)
    assert array.dtype == np.uint8 and array.shape == (4, 180, 320, 3)
    for i, k in enumerate(asked):
        png = os.path.join(out, "frame_%d.png" % k)
        if not os.path.exists(png):
            support.tumble("render", "lessons/intermediate_axis", "--frame", k, "--width", 320,
                           "--height", 180, "-q", "-o", png)
        np.testing.assert_array_equal(array[i], support.decode_png(png), err_msg="frame %d" % k)
    # Frames differ (the body turns): the comparison above is not of blank pictures.
    assert np.abs(array[1].astype(int) - array[2].astype(int)).sum() > 0


def test_one_frame_and_a_still_file():
    out = support.scratch("render_still")
    one = tumble.render("default", frame=30, preview=True, **SMALL)
    assert one.shape == (180, 320, 3)
    still = tumble.render("default", output=os.path.join(out, "s.png"), frame=30, preview=True,
                          **SMALL)
    assert still.frames == 1 and os.fspath(still).endswith("s.png")
    np.testing.assert_array_equal(one, support.decode_png(os.fspath(still)))
    assert "<img" in still._repr_html_()


def test_a_video_output_and_a_comparison_show_inline():
    out = support.scratch("render_video")
    video = tumble.render("default", output=os.path.join(out, "v.mp4"), duration=0.5,
                          preview=True, **SMALL)
    assert video.frames == 30 and os.path.getsize(os.fspath(video)) > 0
    assert "<video" in video._repr_html_()
    probe = support.subprocess.run(
        ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
         "stream=nb_read_frames", "-of", "csv=p=0", os.fspath(video)],
        capture_output=True, text=True, check=True)
    assert int(probe.stdout) == 30
    both = tumble.render("lessons/intermediate_axis", output=os.path.join(out, "c.mp4"),
                         compare=["euler", "rk4"], duration=0.25, preview=True, **SMALL)
    assert both.frames == 15


def test_bad_picture_options_raise_badinput():
    with pytest.raises(tumble.BadInput, match="frame"):
        tumble.render("default", frames=[100000], **SMALL)
    with pytest.raises(tumble.BadInput):
        tumble.render("default", output="x.unknown", **SMALL)
    with pytest.raises(tumble.BadInput, match="--compare"):
        tumble.render("default", output="x.mp4", compare=["euler", "nope"], **SMALL)
