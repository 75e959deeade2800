"""texture(): the C++ call's uvs, bit for bit, with its report and the command-line tool's options."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import norm_preserving
from conftest import mesh_path, quad_grid


def test_the_module_tested_is_the_build_trees():
    """ctest puts the build tree's module first on the path: an installed one is not tested."""
    built = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0]).resolve()
    assert pathlib.Path(norm_preserving.__file__).resolve().parent == built


def cpp_uv(name, tmp_path, guess="xy"):
    """The uvs of the C++ call the module wraps (test/uv_bits.cpp) on one of CGAL's meshes."""
    out = tmp_path / f"{name}.raw"
    subprocess.run([os.environ["NP_UV_BITS"], str(mesh_path(name)), "--guess", guess, "--raw", str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    return np.fromfile(out, dtype=np.float64).reshape(-1, 2)


@pytest.mark.parametrize("name, guess", [("cow", "xy"), ("bunny00", "xy"), ("cow", "combination")])
def test_same_uv_bits_as_the_cpp_call(name, guess, tmp_path, request):
    vertices, faces = norm_preserving.read_mesh(mesh_path(name))
    if (name, guess) == ("cow", "xy"):
        uv, _ = request.getfixturevalue("cow_texture")  # texture(*read_mesh(cow.off)), solved once
    else:
        uv, _ = norm_preserving.texture(vertices, faces, guess=guess)
    assert uv.dtype == np.float64 and uv.shape == (len(vertices), 2)
    assert np.array_equal(uv.view(np.uint64), cpp_uv(name, tmp_path, guess).view(np.uint64))


def test_arrays_read_in_place_give_the_same_bits_in_any_dtype_and_layout(cow):
    """float32 vertices are read as the doubles they hold; any integer dtype and strides of faces."""
    vertices, faces = cow
    single = vertices.astype(np.float32)
    reference, _ = norm_preserving.texture(single.astype(np.float64), faces)
    for v, f in [(single, faces.astype(np.int32)),
                 (np.asfortranarray(single), np.asfortranarray(faces.astype(np.uint16))),
                 (np.hstack([single, single])[:, :3], np.hstack([faces, faces])[:, 3:]),
                 (single.tolist(), faces.tolist())]:
        uv, _ = norm_preserving.texture(v, f)
        assert np.array_equal(uv.view(np.uint64), reference.view(np.uint64))


def test_one_finite_uv_per_vertex_fitted_into_the_unit_square(cow_texture):
    uv, report = cow_texture
    assert np.isfinite(uv).all() and uv.min() >= 0 and uv.max() <= 1
    assert np.isclose(uv.max(), 1.0)  # uniform fit: the longer side spans [0, 1]
    assert report.status == norm_preserving.ErrorCode.OK and report.message == ""


def test_the_report_holds_every_field_of_the_cpp_report(cow, cow_texture):
    vertices, faces = cow
    uv, report = cow_texture
    assert report.components == 1 and len(report.reports) == 1
    assert (report.isolated_vertices, report.welded_vertices, report.repeated_corners, report.point_components) == (0, 1, 0, 0)
    assert not report.interrupted and report.seconds > 0
    component = report.reports[0]
    assert component.vertices == len(vertices) - report.welded_vertices and component.edges > len(faces)
    assert report.objective == component.objective < component.initial_objective
    assert component.constraints == 2 * component.edges and 0 < component.active_constraints <= component.constraints
    assert component.max_constraint_violation >= 0
    assert component.sign_refinement_objectives == [] and component.euclidean_stress == []
    solver = component.solver
    assert solver.status == norm_preserving.SolverStatus.CONVERGED and solver.message == "" and not solver.interrupted
    assert solver.method.startswith("ADMM")
    assert solver.has_statistics and solver.iterations > 0 and solver.kkt_residual >= 0
    assert 0 <= report.optimality_gap == solver.optimality_gap < 1e-2
    steps = component.timings
    total = sum(getattr(steps, s) for s in ("extraction", "guess", "solve", "sign_refinement", "euclidean_refinement",
                                            "write_back"))
    assert 0 < total <= component.seconds * 1.01 and component.seconds <= report.seconds
    assert 0 < solver.assembly_seconds + solver.factorization_seconds + solver.iteration_seconds <= steps.solve * 1.01
    fixed = sorted((component.fixed_a, component.fixed_b))
    assert any(set(fixed) <= set(face) for face in faces.tolist())  # the fixed pair is an edge
    assert report.distortion.faces == len(faces) and report.distortion.edges == component.edges
    assert report.distortion.flipped_faces > 0  # a closed surface folds


def test_the_distortion_is_that_of_measure_distortion(cow, cow_texture):
    uv, report = cow_texture
    measured = norm_preserving.measure_distortion(*cow, uv)
    for name in ("faces", "edges", "scale", "edge_length_error", "l1_edge_length_error", "l1_objective",
                 "mean_angle_distortion", "max_angle_distortion", "area_distortion", "l2_stretch",
                 "linf_stretch", "flipped_faces", "flipped_area_fraction", "degenerate_uv_faces"):
        assert getattr(measured, name) == getattr(report.distortion, name), name


def test_tiles_scale_u_and_v(cow, cow_texture):
    uv, _ = cow_texture
    tiled, _ = norm_preserving.texture(*cow, tiles=(2, 3))
    assert np.allclose(tiled, uv * [2, 3], rtol=0, atol=1e-12)


def test_fit(cow):
    vertices, faces = cow
    larger = 10 * vertices  # the cow is about one unit long
    uniform, _ = norm_preserving.texture(larger, faces)
    clamped, _ = norm_preserving.texture(larger, faces, fit="clamp")
    unfitted, _ = norm_preserving.texture(larger, faces, fit="none")
    assert uniform.min() >= 0 and uniform.max() == 1
    assert clamped.min() >= 0 and clamped.max() <= 1 and not np.array_equal(clamped, uniform)
    assert unfitted.max() - unfitted.min() > 5  # in mesh units


def test_the_fixed_pair_is_held(cow):
    vertices, faces = cow
    a, b = int(faces[10, 0]), int(faces[10, 1])
    _, report = norm_preserving.texture(vertices, faces, fixed_pair=(a, b))
    assert (report.reports[0].fixed_a, report.reports[0].fixed_b) == (a, b)


def test_coincident_vertices_are_welded_unless_kept_apart():
    # Two triangles of a square, each with its own copy of the shared edge's ends.
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 0, 0], [1, 1, 0], [0, 1, 0.2]], dtype=float)
    faces = np.array([[0, 1, 2], [3, 4, 5]])
    uv, report = norm_preserving.texture(vertices, faces)
    assert report.welded_vertices == 2 and report.components == 1
    assert np.array_equal(uv[0], uv[3]) and np.array_equal(uv[2], uv[4])
    uv, report = norm_preserving.texture(vertices, faces, keep_coincident=True)
    assert report.welded_vertices == 0 and report.components == 2


def test_refinements_and_exact_quality_fill_their_report_fields(cow):
    _, report = norm_preserving.texture(*cow, refine_signs=True, refine_euclidean=True)
    component = report.reports[0]
    assert len(component.sign_refinement_objectives) == component.sign_refinement_rounds + 1
    assert component.euclidean_iterations > 0 and len(component.euclidean_stress) == component.euclidean_iterations + 1
    _, exact = norm_preserving.texture(*cow, quality="exact")
    assert exact.optimality_gap <= 1e-9 or exact.reports[0].solver.status == norm_preserving.SolverStatus.PRECISION_LIMIT


def test_a_time_limit_returns_the_best_point_with_a_warning(bunny):
    uv, report = norm_preserving.texture(*bunny, time_limit=1e-6)
    assert report.reports[0].solver.status == norm_preserving.SolverStatus.TIME_LIMIT
    assert report.reports[0].solver.message != "" and np.isfinite(uv).all()


def test_polygons_of_mixed_sizes_as_index_lists():
    vertices, quads = quad_grid(6, 8)
    uv_quads, _ = norm_preserving.texture(vertices, quads)
    as_lists, _ = norm_preserving.texture(vertices, [list(q) for q in quads])
    assert np.array_equal(uv_quads, as_lists)
    # One quad split into two triangles: faces of three and four corners.
    mixed = [list(q) for q in quads[1:]] + [[quads[0][0], quads[0][1], quads[0][2]], [quads[0][0], quads[0][2], quads[0][3]]]
    uv, report = norm_preserving.texture(vertices, mixed)
    assert report.components == 1 and np.isfinite(uv).all()


def test_a_vertex_on_no_face_gets_nan():
    vertices, quads = quad_grid(2, 2)
    vertices = np.vstack([vertices, [[5.0, 5.0, 5.0]]])
    uv, report = norm_preserving.texture(vertices, quads)
    assert report.isolated_vertices == 1
    assert np.isnan(uv[-1]).all() and np.isfinite(uv[:-1]).all()


def test_progress_is_called_with_a_growing_fraction_and_does_not_change_the_bits(cow, cow_texture):
    """A callback that returns None (as most do) or a true value lets the call go on."""
    seen = []

    def record(p):
        seen.append((p.fraction, p.components, p.components_done, p.seconds))
        return None if len(seen) % 2 else np.True_

    uv, _ = norm_preserving.texture(*cow, progress=record)
    assert len(seen) >= 2
    fractions = [s[0] for s in seen]
    assert fractions == sorted(fractions) and 0 <= fractions[0] and fractions[-1] == 1
    assert all(s[1] == 1 for s in seen) and seen[-1][2] == 1
    plain, _ = cow_texture
    assert np.array_equal(uv.view(np.uint64), plain.view(np.uint64))


@pytest.mark.parametrize("answer", [False, np.False_, 0, ""], ids=["False", "numpy.False_", "0", "empty string"])
def test_progress_returning_a_false_value_stops_the_call(cow, answer):
    calls = []

    def stop(progress):
        calls.append(progress.fraction)
        return answer

    with pytest.raises(RuntimeError, match="interrupted by the progress callback"):
        norm_preserving.texture(*cow, progress=stop)
    assert len(calls) == 1


def test_progress_returning_a_value_of_no_truth_raises_its_error(cow):
    """numpy's error for the truth of an array of two values stops the call, and is raised."""
    with pytest.raises(ValueError, match="truth value of an array"):
        norm_preserving.texture(*cow, progress=lambda p: np.array([True, False]))


def test_an_exception_of_the_progress_callback_is_raised_again(cow):
    class Stop(Exception):
        pass

    def fail(progress):
        raise Stop("enough")

    with pytest.raises(Stop, match="enough"):
        norm_preserving.texture(*cow, progress=fail)
