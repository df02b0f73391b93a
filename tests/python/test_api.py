# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module against the core and the command line: the same results, stages, verdicts,
statistics and messages; the GIL released; progress and cancel; pictures as `sculpt render`
draws them."""
import _thread
import gc
import json
import threading

import matplotlib.image
import numpy as np
import pytest

import sculpt


@pytest.fixture(scope="module")
def star():
    return sculpt.reconstruct(sculpt.example("star"), method="paper")


@pytest.fixture(scope="module")
def bumpy():
    return sculpt.reconstruct(sculpt.example("bumpy"))


def test_a_closed_curve_and_a_closed_surface_with_their_verdicts(star, bumpy):
    assert star.dimension == 2 and bumpy.dimension == 3
    for result in (star, bumpy):
        assert result.manifold
        assert result.verdict.startswith("closed")
        n = len(result.samples)
        assert result.stats["samples"] == n
        assert result.surface.min() >= 0 and result.surface.max() < n
        assert len(np.unique(result.surface)) == n  # every sample on the result
    assert star.surface.shape == (200, 2)  # a closed curve: as many edges as samples
    # Euler: a closed genus-0 surface of n vertices has 2n - 4 triangles.
    assert bumpy.surface.shape == (2 * len(bumpy.samples) - 4, 3)


def test_every_stage_is_consistent_with_the_others(star):
    n = len(star.samples)
    stages = star.stages
    cells = stages["delaunay"].cells
    assert cells.shape == (stages["delaunay"].cell_count, 3)
    assert cells.max() == n + 4 - 1  # samples and the four box corners
    poles = stages["poles"]
    assert np.all(poles.radius > 0)
    assert poles.center.shape == (len(poles.radius), 2)
    # A pole is the circumcentre of its cell: as far from each of the cell's sites.
    distances = np.linalg.norm(star.sites[poles.sites] - poles.center[:, None, :], axis=2)
    assert np.allclose(distances, poles.radius[:, None], rtol=1e-9)
    assert poles.positive_pole.shape == (n,) and poles.positive_pole.max() < len(poles.radius)
    propagation = stages["propagation"]
    assert len(propagation.labels) == len(poles.radius)
    # The paper keeps the first label: replaying the events gives the final labels.
    replayed = np.zeros(len(poles.radius), dtype=np.uint8)
    replayed[propagation.events["pole"]] = propagation.events["label"]
    assert np.array_equal(replayed, propagation.labels)
    assert sculpt.LABELS[propagation.events["label"][0]] == "outer"  # a convex seed
    assert np.all(propagation.labels[stages["insertion"].inserted_poles] == 2)  # OUP: outer
    assert np.all(stages["seeds"].outer_seeds < len(poles.radius))


def test_the_alpha_shape_takes_a_given_radius():
    torso = sculpt.example("torso")
    chosen = sculpt.reconstruct(torso, method="alpha-shape")
    again = sculpt.reconstruct(torso, method="alpha-shape", alpha=chosen.stats["alpha"])
    assert again.stats["solid_cells"] == chosen.stats["solid_cells"] == len(chosen.solid)
    smaller = sculpt.reconstruct(torso, method="alpha-shape", alpha=chosen.stats["alpha"] / 2)
    assert smaller.stats["alpha"] == pytest.approx(chosen.stats["alpha"] / 2)
    assert len(smaller.solid) < len(chosen.solid)
    with pytest.raises(sculpt.InputError, match="alpha must be a positive radius"):
        sculpt.reconstruct(torso, method="alpha-shape", alpha=float("inf"))


def test_stage_views_are_read_only_and_keep_the_result_alive():
    sites = sculpt.reconstruct(sculpt.example("star")).sites
    gc.collect()  # the result is gone from Python; its views must still hold it
    assert sites.shape == (204, 2)  # 200 samples and 4 box corners
    with pytest.raises(ValueError):
        sites[0, 0] = 5


def test_samples_and_surface_are_writable_arrays_of_ones_own(tmp_path):
    # What Open3D's and trimesh's constructors take; changing them changes no reconstruction.
    result = sculpt.reconstruct(sculpt.example("bumpy"))
    samples, surface = result.samples, result.surface
    assert samples.flags.writeable and surface.flags.writeable
    assert result.samples is samples and result.surface is surface  # made once
    samples[:] = 0
    surface[:] = 0
    sculpt.write(result, tmp_path / "kept.off")
    sculpt.write(sculpt.reconstruct(sculpt.example("bumpy")), tmp_path / "fresh.off")
    assert (tmp_path / "kept.off").read_bytes() == (tmp_path / "fresh.off").read_bytes()


@pytest.mark.parametrize("example, method", [("bumpy", "robust"), ("blob", "paper"),
                                             ("bumpy", "cocone")])
def test_the_statistics_and_verdict_are_the_command_lines(example, method, sculpt_cli, tmp_path):
    stats = tmp_path / "stats.json"
    run = sculpt_cli("reconstruct", "--example", example, "--method", method,
                     "-o", tmp_path / ("out.stl" if example == "bumpy" else "out.svg"),
                     "--stats", stats)
    assert run.returncode == 0, run.stderr
    cli = json.loads(stats.read_text())
    # As the command line computes: without keeping the triangulations, and an example as the
    # kind it is (these are closed).
    result = sculpt.reconstruct(sculpt.example(example), method=method, kind="closed",
                                keep_triangulations=False)
    timings = {"input", "read_seconds", "write_seconds", "total_seconds", "stages"}
    assert set(result.stats) == set(cli) - {"input", "read_seconds", "write_seconds"}
    for field in set(cli) - timings:
        assert result.stats[field] == cli[field], field
    assert [s["name"] for s in result.stats["stages"]] == [s["name"] for s in cli["stages"]]
    assert f"verdict: {result.verdict}" in run.stdout


def test_every_method_by_name_where_it_applies(sculpt_cli):
    help_text = sculpt_cli("reconstruct", "--help").stdout
    curve, surface = sculpt.example("star"), sculpt.example("bumpy")
    assert list(sculpt.methods())[0] == sculpt.DEFAULT_METHOD
    for name in sculpt.methods():
        assert name in help_text
        for points in (curve, surface):
            dimension = points.shape[1]
            try:
                result = sculpt.reconstruct(points, method=name)
            except sculpt.InputError as error:  # the NN-crust has no surfaces, the co-cone no curves
                assert name in ("nn-crust", "cocone", "tight-cocone", "advancing-front", "alpha-shape")
                assert "\n" not in str(error)
                continue
            assert result.method == name and result.stats["method"] == name
            assert result.surface.shape[1] == dimension
            assert sculpt.stages(name, dimension)[0] == "samples"


def test_bad_input_raises_the_command_lines_message(sculpt_cli, tmp_path):
    collinear = tmp_path / "line.xyz"
    collinear.write_text("".join(f"{k} {2 * k} {3 * k}\n" for k in range(10)))
    malformed = tmp_path / "broken.xyz"
    malformed.write_text("1 2 3\n4 five 6\n")
    for path in (collinear, malformed):
        run = sculpt_cli("reconstruct", path, "-o", tmp_path / "out.stl")
        assert run.returncode == 1
        with pytest.raises(sculpt.InputError) as raised:
            sculpt.reconstruct(sculpt.read_points(str(path)))
        assert run.stderr == f"sculpt: error: {raised.value}\n"

    # The arguments themselves: an InputError (a ValueError) each, in one line.
    star = sculpt.reconstruct(sculpt.example("star"))
    bad_calls = {
        r"shape \(n, 2\) or \(n, 3\), not \(4, 4\)": lambda: sculpt.reconstruct(np.zeros((4, 4))),
        r"not \(6,\)": lambda: sculpt.reconstruct(np.zeros(6)),
        "must be numbers": lambda: sculpt.reconstruct([["a", "b"], ["c", "d"]]),
        "methods: robust, paper": lambda: sculpt.reconstruct(star.samples, method="sculpting"),
        "kinds: closed, bordered": lambda: sculpt.reconstruct(star.samples, kind="open"),
        "rules: auto": lambda: sculpt.reconstruct(star.samples, rule="best"),
        "box factor": lambda: sculpt.reconstruct(star.samples, box_factor=1e308),
        "stages: samples": lambda: sculpt.render(star, stage="nothing"),
        "does not reconstruct in 3D": lambda: sculpt.stages("nn-crust", 3),
        r"examples\(\) lists them": lambda: sculpt.example("teapot"),
        r"size is \(width, height\)": lambda: sculpt.render(star, size=(0, 10)),
        "from 1 to 8192 pixels": lambda: sculpt.render(star, size=(20000, 10)),
        "zoom must be a positive": lambda: sculpt.render(star, zoom=0),
        "finite angles": lambda: sculpt.render(star, yaw=float("nan")),
        "ball_every": lambda: sculpt.render(star, ball_every=0),
        "step must be": lambda: sculpt.render(star, step=-2),
        # Keywords that would do nothing where they are given.
        "alpha= is the radius of the method alpha-shape": lambda: sculpt.reconstruct(
            star.samples, alpha=0.3),
        "rule= chooses the facets of the surface": lambda: sculpt.reconstruct(
            star.samples, method="crust", rule="skin"),
        "only robust chooses the kind": lambda: sculpt.reconstruct(
            star.samples, method="paper", kind="automatic"),
        "step= chooses a moment of a replay": lambda: sculpt.render(star, stage="poles", step=3),
        "wireframe= draws a reconstructed surface": lambda: sculpt.render(star, wireframe=True),
        "turns a 3D camera": lambda: sculpt.render(star, yaw=1.0),
        "ascii= writes .stl and .ply as text": lambda: sculpt.write(star, "/tmp/never.svg",
                                                                    ascii=True),
        "keep_triangulations": lambda: sculpt.render(
            sculpt.reconstruct(star.samples, method="paper", keep_triangulations=False),
            stage="sculpted-delaunay"),
    }
    for message, call in bad_calls.items():
        with pytest.raises(sculpt.InputError, match=message) as raised:
            call()
        assert "\n" not in str(raised.value)


def test_repeated_points_are_refused_until_merged():
    points = sculpt.example("bumpy")
    repeated = np.vstack([points, points[:5]])
    with pytest.raises(sculpt.DuplicatePoints, match="merge_duplicates=True"):
        sculpt.reconstruct(repeated)
    merged = sculpt.merge_duplicates(repeated)
    assert np.array_equal(merged, points)
    assert sculpt.reconstruct(merged).manifold
    assert sculpt.reconstruct(repeated, merge_duplicates=True).stats["samples"] == len(points)


def test_plain_python_values_are_accepted(tmp_path):
    star = sculpt.example("star")
    result = sculpt.reconstruct(star.tolist())  # a list of points
    assert result.manifold and result.samples.dtype == np.float64
    path = tmp_path / "star.xy"
    np.savetxt(path, star)
    assert np.allclose(sculpt.read_points(path), star)  # a pathlib path
    sculpt.write(result, tmp_path / "star.svg")
    assert (tmp_path / "star.svg").exists()
    assert sculpt.render(result, size=50).shape == (50, 50, 4)  # one number: a square
    assert list(sculpt.methods(dimension=2)) == [
        "robust", "paper", "crust", "nn-crust", "power-crust", "boissonnat"]


def test_reconstruction_releases_the_gil():
    points = sculpt.example("torus")
    ticks, marks = [0], []

    def reconstruct():  # the callback runs inside the core: it marks the main thread's count
        sculpt.reconstruct(points, progress=lambda stage, fraction: marks.append(ticks[0]))

    worker = threading.Thread(target=reconstruct)
    worker.start()
    while worker.is_alive():
        ticks[0] += 1
    worker.join()
    # Holding the GIL from its first stage to its last, the core would leave this thread no turn.
    assert marks[-1] - marks[0] > 10000


def test_ctrl_c_interrupts_a_reconstruction():
    seen = []

    def interrupt_once_poles_start(stage, fraction):
        seen.append(stage)
        if stage == "poles":
            _thread.interrupt_main()  # as Ctrl-C in a notebook; the core checks at its next report

    with pytest.raises(KeyboardInterrupt):
        sculpt.reconstruct(sculpt.example("bumpy"), progress=interrupt_once_poles_start)
    assert "surface" not in seen  # stopped there, not after the run


def test_progress_is_reported_and_can_cancel():
    points = sculpt.example("bumpy")
    seen = []
    sculpt.reconstruct(points, progress=lambda stage, fraction: seen.append((stage, fraction)))
    stages = [stage for stage, _ in seen]
    assert "delaunay" in stages and "poles" in stages
    assert all(0 <= fraction <= 1 for _, fraction in seen)
    for stage in set(stages):  # each stage starts at 0 and ends at 1
        assert (stage, 0.0) in seen and (stage, 1.0) in seen, stage
    with pytest.raises(sculpt.Cancelled):
        sculpt.reconstruct(points, progress=lambda stage, fraction: stage != "poles")

    # A callable of three arguments also gets the whole run's fraction: a bar that fills once.
    overall = []
    sculpt.reconstruct(points, progress=lambda stage, fraction, whole: overall.append(whole))
    assert overall == sorted(overall) and overall[0] >= 0 and overall[-1] == pytest.approx(1)

    def failing(stage, fraction):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        sculpt.reconstruct(points, progress=failing)


def test_pictures_are_the_command_lines(star, sculpt_cli, tmp_path):
    shots = tmp_path / "shots.json"
    png = tmp_path / "poles.png"
    shots.write_text(json.dumps({"shots": [
        {"example": "star", "method": "paper", "stage": "poles", "size": "320x240",
         "output": str(png)}]}))
    run = sculpt_cli("render", "--shots", shots)
    assert run.returncode == 0, run.stderr
    expected = np.rint(matplotlib.image.imread(png) * 255).astype(np.uint8)
    image = sculpt.render(star, stage="poles", size=(320, 240))
    assert image.shape == (240, 320, 4) and image.dtype == np.uint8
    assert np.abs(image.astype(int) - expected).max() <= 2
    bumpy = sculpt.reconstruct(sculpt.example("bumpy"))
    whole = sculpt.render(bumpy, stage="delaunay", size=120)
    cut = sculpt.render(bumpy, stage="delaunay", size=120, clip=(0.5, 0, 90))
    assert np.count_nonzero(np.any(cut != whole, axis=2)) > 1000
    with pytest.raises(sculpt.InputError, match="the clip must be"):
        sculpt.render(bumpy, stage="delaunay", clip=(1.5, 0, 0))
    # a true section, the colour-blind palette, the polar balls limited
    section = sculpt.render(bumpy, stage="delaunay", size=120, section=(0.5, 0, 90))
    assert np.count_nonzero(np.any(section != cut, axis=2)) > 1000
    with pytest.raises(sculpt.InputError, match="section is"):
        sculpt.render(bumpy, stage="delaunay", section=(0.5, 0))
    safe = sculpt.render(star, stage="poles", size=(320, 240), palette="colour-blind")
    assert np.count_nonzero(np.any(safe != image, axis=2)) > 1000
    with pytest.raises(sculpt.InputError, match="no palette"):
        sculpt.render(star, stage="poles", palette="pink")
    balls = sculpt.render(bumpy, stage="poles", size=120, polar_balls=True, ball_limit=10)
    assert np.count_nonzero(np.any(balls != sculpt.render(bumpy, stage="poles", size=120),
                                   axis=2)) > 100
    other = sculpt.render(star, stage="surface", size=(320, 240))
    assert np.count_nonzero(np.any(other != image, axis=2)) > 1000
    # from another thread too (the GL context follows the caller)
    results = []
    worker = threading.Thread(target=lambda: results.append(sculpt.render(star, stage="poles",
                                                                          size=(320, 240))))
    worker.start()
    worker.join()
    assert np.array_equal(results[0], image)


def test_writes_every_file_or_none(bumpy, tmp_path):
    stl, solid = tmp_path / "bumpy.stl", tmp_path / "bumpy.vtu"
    sculpt.write(bumpy, str(stl), solid=str(solid))
    assert stl.stat().st_size == 84 + 50 * len(bumpy.surface)  # binary STL
    assert solid.stat().st_size > 0
    with pytest.raises(sculpt.InputError, match="cannot write a solid"):
        sculpt.write(bumpy, str(tmp_path / "again.stl"), solid=str(tmp_path / "again.txt"))
    assert not (tmp_path / "again.stl").exists()


def test_write_never_replaces_a_file_read_points_read(tmp_path):
    # A mesh read for its vertices and written back under its own name would lose its faces.
    mesh = tmp_path / "sphere.off"
    sculpt.write(sculpt.reconstruct(sculpt.example("bumpy")), str(mesh))
    original = mesh.read_bytes()
    points = sculpt.read_points(mesh)
    result = sculpt.reconstruct(points)
    for name in (mesh, tmp_path / "sub" / ".." / "sphere.off", tmp_path / "." / "sphere.off"):
        (tmp_path / "sub").mkdir(exist_ok=True)
        with pytest.raises(sculpt.InputError, match="never replaces an input"):
            sculpt.write(result, name)
    assert mesh.read_bytes() == original
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sphere.off", "sub"]


def test_a_method_without_a_solid_writes_none(sculpt_cli, tmp_path):
    cocone = sculpt.reconstruct(sculpt.example("bumpy"), method="cocone")
    with pytest.raises(sculpt.InputError) as raised:
        sculpt.write(cocone, tmp_path / "a.stl", solid=tmp_path / "a.vtu")
    assert str(raised.value) == (
        "the method cocone builds no solid (robust, paper, alpha-shape, tight-cocone, boissonnat do)")
    assert list(tmp_path.iterdir()) == []
    run = sculpt_cli("reconstruct", "--example", "bumpy", "--method", "cocone",
                     "-o", tmp_path / "a.stl", "--solid", tmp_path / "a.vtu")
    assert run.returncode == 2
    assert f"usage error: {raised.value}" in run.stderr
    assert list(tmp_path.iterdir()) == []


def test_arrays_beyond_the_point_budget_are_refused_before_any_copy():
    # A broadcast view of 10^9 rows costs 24 bytes; a copy of it would cost 24 GB.
    huge = np.broadcast_to(np.array([1.0, 2.0, 3.0]), (10**9, 3))
    with pytest.raises(sculpt.InputError) as raised:
        sculpt.reconstruct(huge)
    assert str(raised.value) == ("points: an array of 1000000000 points (24.0 GB as float64) is "
                                 "more than the input limit of 50000000 points "
                                 "(SCULPT_MAX_POINTS raises it)")
    with pytest.raises(sculpt.InputError, match="real numbers, not complex"):
        sculpt.reconstruct(sculpt.example("star").astype(complex))


def test_a_signal_during_write_leaves_no_temporary(tmp_path):
    # A child process writes a large surface over and over; SIGTERM ends it mid-write.
    import os
    import signal
    import subprocess
    import sys
    import time
    script = (
        "import sculpt, sys\n"
        "r = sculpt.reconstruct(sculpt.example('bumpy'))\n"
        "print('ready', flush=True)\n"
        "while True:\n"
        "    sculpt.write(r, sys.argv[1], ascii=True, solid=sys.argv[2])\n")
    for delay in (0.0, 0.05, 0.2):
        for name in os.listdir(tmp_path):
            os.remove(tmp_path / name)
        child = subprocess.Popen(
            [sys.executable, "-c", script, str(tmp_path / "s.ply"), str(tmp_path / "s.vtu")],
            stdout=subprocess.PIPE, text=True)
        assert child.stdout.readline() == "ready\n"
        time.sleep(delay)
        child.send_signal(signal.SIGTERM)
        assert child.wait(timeout=60) == -signal.SIGTERM
        assert sorted(os.listdir(tmp_path)) in ([], ["s.ply", "s.vtu"]), delay


def noisy_sphere(n, noise, seed=4):
    """n samples on a sphere of spacing about 1, moved along the normal by noise x spacing."""
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(n, 3))
    v /= np.linalg.norm(v, axis=1)[:, None]
    return v * (np.sqrt(n / (4 * np.pi)) + noise * rng.normal(size=n))[:, None]


def test_noisy_samples_are_smoothed_first_and_the_command_line_agrees(sculpt_cli, tmp_path):
    points = noisy_sphere(4000, 0.4)
    cleaned = sculpt.reconstruct(points)
    assert cleaned.stats["cleaned"] and cleaned.stats["noise"] >= 0.3
    assert cleaned.stats["euler_characteristic"] == 2 and cleaned.manifold
    assert np.array_equal(cleaned.given_samples, points)
    assert not np.array_equal(cleaned.samples, points)  # the surface is on the smoothed ones
    as_given = sculpt.reconstruct(points, clean="none")
    assert not as_given.stats["cleaned"] and as_given.given_samples is None
    assert "the samples are noisy" in as_given.verdict
    with pytest.raises(sculpt.InputError, match="no cleaning 'bilateral'"):
        sculpt.reconstruct(points, clean="bilateral")

    path = tmp_path / "noisy.xyz"
    np.savetxt(path, points, fmt="%.17g")
    for clean, expected in (("auto", True), ("none", False), ("jet", True)):
        stats = tmp_path / f"{clean}.json"
        run = sculpt_cli("reconstruct", path, "-o", tmp_path / "out.ply", "--clean", clean,
                         "--stats", stats)
        assert run.returncode == 0, run.stderr
        report = json.loads(stats.read_text())
        assert report["cleaned"] == expected and report["noise"] == pytest.approx(
            cleaned.stats["noise"])
        assert ("smoothed" in run.stdout) == expected
    run = sculpt_cli("reconstruct", path, "-o", tmp_path / "out.ply", "--clean", "bilateral")
    assert run.returncode == 2 and len(run.stderr.strip().splitlines()) == 1


def test_outliers_are_removed_where_asked_and_the_command_line_agrees(sculpt_cli, tmp_path):
    points = noisy_sphere(3000, 0.05)
    strays = points[:5] * 1.4  # far outside, 6 spacings and more, among the others
    given = np.insert(points, [10, 500, 1000, 2000, 2999], strays, axis=0)
    kept = sculpt.reconstruct(given)  # clean samples: the automatic cleaning leaves them
    assert not kept.stats["cleaned"] and kept.removed_outliers is None
    cleaned = sculpt.reconstruct(given, clean="outliers")
    assert cleaned.stats["cleaned"] and not cleaned.stats["smoothed"]
    assert cleaned.stats["outliers_removed"] == 5
    assert list(cleaned.removed_outliers) == [10, 501, 1002, 2003, 3003]
    assert np.array_equal(cleaned.samples, points)  # the others as given, in their order
    assert np.array_equal(cleaned.given_samples, given)
    assert "5 outliers removed, not on it" in cleaned.verdict
    lean = sculpt.reconstruct(given, clean="outliers", keep_triangulations=False)
    assert lean.given_samples is None and list(lean.removed_outliers) == [10, 501, 1002, 2003, 3003]

    path = tmp_path / "strays.xyz"
    np.savetxt(path, given, fmt="%.17g")
    stats = tmp_path / "outliers.json"
    out = tmp_path / "out.off"
    run = sculpt_cli("reconstruct", path, "-o", out, "--clean", "outliers", "--stats", stats)
    assert run.returncode == 0, run.stderr
    assert json.loads(stats.read_text())["outliers_removed"] == 5
    assert "outliers removed" in run.stdout
    assert out.read_text().splitlines()[1].split()[0] == "3000"  # the vertices are those kept


def thin_torus(around, along=40, tube_radius=0.11):
    """Samples in rings of `around` around a tube of a torus, each ring turned half a step."""
    ring = np.repeat(np.arange(along), around)
    theta = ring * 2 * np.pi / along
    phi = np.tile(np.arange(around) * 2 * np.pi / around, along) + (ring % 2) * np.pi / around
    r = 1 + tube_radius * np.cos(phi)
    return np.c_[r * np.cos(theta), r * np.sin(theta), tube_radius * np.sin(phi)]


def test_a_handle_thinner_than_the_spacing_is_named_suspect_with_its_loop():
    # A tube four samples around: the handle is real but no sample lies around its neck.
    thin = sculpt.reconstruct(thin_torus(4), clean="none")
    assert thin.stats["euler_characteristic"] == 0 and thin.manifold
    assert thin.stats["thin_handles"] == 1
    handles = thin.stages["handles"].thin
    assert handles.dtype.names == ("loop", "width_over_spacing")
    loop = handles["loop"][0]
    assert len(set(loop // 4)) == 1  # one ring of the tube: the loop around its neck
    assert 0 < handles["width_over_spacing"][0] <= 2
    assert "1 handle suspect" in thin.verdict
    # Five around (the samples as far apart around as along): the same genus, nothing suspect.
    sampled = sculpt.reconstruct(thin_torus(5, tube_radius=0.12), clean="none")
    assert sampled.stats["euler_characteristic"] == 0
    assert sampled.stats["thin_handles"] == 0 and len(sampled.stages["handles"].thin) == 0
    assert "suspect" not in sampled.verdict
