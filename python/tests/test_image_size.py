"""raylab.render follows the command line's image-size rule: one side keeps the scene's shape,
both in another shape widen the view, with the same pixels as `raylab render`."""

import subprocess

import numpy as np

import raylab


def test_one_side_keeps_the_scenes_shape():
    # demo is 800 x 450.
    assert raylab.render("demo", width=64, spp=1, threads=2).shape == (36, 64, 3)
    assert raylab.render("demo", height=9, spp=1, threads=2).shape == (9, 16, 3)


def test_a_taller_image_is_the_command_lines_widened_view(tmp_path, binary):
    image = raylab.render("demo", width=32, height=48, spp=1, threads=2)
    out = tmp_path / "cli.pfm"
    subprocess.run([binary, "render", "demo", "--width", "32", "--height", "48", "--spp", "1", "-q", "-o", str(out)],
                   check=True, capture_output=True)
    raylab.write_image(tmp_path / "py.pfm", image)
    assert (tmp_path / "py.pfm").read_bytes() == out.read_bytes()
    # Widened, not cropped: the middle rows hold the scene's own 32 x 18 frame.
    own = raylab.render("demo", width=32, height=18, spp=1, threads=2)
    assert np.abs(image[15:33] - own).mean() < 0.01
