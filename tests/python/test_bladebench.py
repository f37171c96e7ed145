"""The bladebench Python module against closed forms and the command line's own semantics.

Run by ctest (test python.pytest) with PYTHONPATH at the built module and BLADEBENCH_SOURCE at the
source tree.
"""
import math
import os
import pathlib

import numpy as np
import pytest

import bladebench

SOURCE = pathlib.Path(os.environ.get("BLADEBENCH_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
CANTILEVER = str(SOURCE / "cases/verification/cantilever_modal_q4.toml")


def oscillator(mu, force, frequencies, kt=1.0e6, harmonics=1):
    """A 1 kg mass on 1e6 N/m with 10 N s/m and a Jenkins contact to the ground (n0 = 30 N)."""
    return bladebench.hbm_sweep(
        mass=np.array([[1.0]]), stiffness=np.array([[1.0e6]]), damping=np.array([[10.0]]),
        force=np.array([force], dtype=complex), frequencies_hz=np.asarray(frequencies, dtype=float),
        contacts=[{"tangential": np.array([1.0]), "kt": kt, "mu": mu, "n0": 30.0}], harmonics=harmonics)


def linear_amplitude(k, force, frequencies):
    w = 2 * math.pi * np.asarray(frequencies)
    return abs(force) / np.abs(k - w**2 + 1j * w * 10.0)


def test_a_stuck_contact_is_a_spring_in_parallel():
    """Far below the slip force (mu n0 = 30 N) the contact sticks: the response is that of k + kt."""
    f = np.linspace(150.0, 260.0, 45)
    out = oscillator(mu=1.0, force=0.01, frequencies=f)
    assert out["converged"].all()
    assert out["amplitude"].shape == (45, 1)
    np.testing.assert_allclose(out["amplitude"][:, 0], linear_amplitude(2.0e6, 0.01, f), rtol=1e-7)


def test_a_contact_without_friction_carries_nothing():
    """mu = 0: the slider slips freely and the oscillator is the linear one of k alone."""
    f = np.linspace(120.0, 200.0, 33)
    out = oscillator(mu=0.0, force=1.0, frequencies=f)
    assert out["converged"].all()
    np.testing.assert_allclose(out["amplitude"][:, 0], linear_amplitude(1.0e6, 1.0, f), rtol=1e-7)


def test_stick_slip_puts_the_peak_between_the_free_and_the_stuck_resonance():
    f = np.arange(140.0, 241.0, 1.0)
    out = oscillator(mu=0.3, force=5.0, frequencies=f, harmonics=5)
    assert out["converged"].all(), out["failures"]
    peak = f[np.argmax(out["amplitude"][:, 0])]
    free, stuck = math.sqrt(1.0e6) / (2 * math.pi), math.sqrt(2.0e6) / (2 * math.pi)
    assert free < peak < stuck
    assert out["coefficients"].shape == (f.size, 1, 11)  # c0, a1, b1, ..., a5, b5
    first = out["coefficients"][:, 0, 1:3]
    np.testing.assert_allclose(np.hypot(first[:, 0], first[:, 1]), out["amplitude"][:, 0], rtol=1e-12)


def test_a_case_runs_and_its_frequencies_scale_with_the_square_root_of_the_modulus():
    base = bladebench.run_case(CANTILEVER)
    stiffer = bladebench.run_case(CANTILEVER, settings=["material.E=4.0e11"])
    table = base["frequencies"]
    assert isinstance(table, bladebench.Table) and isinstance(table, np.recarray)
    assert table.dtype["mode"] == np.int64 and table.dtype["frequency_hz"] == np.float64
    assert list(table["mode"][:3]) == [1, 2, 3]
    # f ~ sqrt(E / rho); to the eigensolver's convergence (Lanczos residuals, 2e-8 seen on mode 1).
    np.testing.assert_allclose(stiffer["frequencies"]["frequency_hz"] / table["frequency_hz"], math.sqrt(2.0),
                               rtol=1e-6)


def test_a_table_becomes_a_data_frame_with_its_columns():
    pandas = pytest.importorskip("pandas")
    table = bladebench.run_case(CANTILEVER)["frequencies"]
    frame = table.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(table.dtype.names)
    np.testing.assert_array_equal(frame["frequency_hz"].to_numpy(), table["frequency_hz"])


def test_mesh_modes_are_complete_and_those_of_the_case():
    modes = bladebench.mesh_modes(CANTILEVER, count=4)
    assert modes["complete"] and modes["sturm_count"] == 4
    assert np.all(np.diff(modes["frequency_hz"]) > 0)
    table = bladebench.run_case(CANTILEVER)["frequencies"]
    hz = table["frequency_hz"][:4]
    np.testing.assert_allclose(modes["frequency_hz"], hz, rtol=1e-8)
    shapes = modes["shapes"]
    assert shapes.shape[1] == 4 and np.isfinite(shapes).all()


def test_the_slepc_eigensolver_runs_in_the_interpreter_and_agrees_with_the_default():
    # The PETSc/SLEPc plugin and the sequential MUMPS each load into a scope of their own: the
    # interpreter's process holds both (a build without the plugin refuses the key as bad input).
    pair_cut = str(SOURCE / "cases/verification/nafems_fv52_pair_cut.toml")
    try:
        sliced = bladebench.run_case(pair_cut, settings=['analysis.eigensolver="slepc"'])["frequencies"]
    except bladebench.InputError as e:
        assert "libslepc-real-dev" in str(e)
        pytest.skip("built without PETSc/SLEPc")
    default = bladebench.run_case(pair_cut)["frequencies"]
    assert sliced.shape == default.shape  # the repeated pair 9/10 whole in both
    np.testing.assert_allclose(sliced["frequency_hz"][3:], default["frequency_hz"][3:], rtol=1e-9)


def test_an_array_of_the_wrong_dtype_or_shape_is_refused_with_the_shape_expected():
    with pytest.raises(bladebench.InputError, match=r"mass: expected dtype float64 and shape \(any, any\), "
                                                    r"got dtype float32"):
        bladebench.hbm_sweep(np.array([[1.0]], dtype=np.float32), np.array([[1.0]]), np.array([[0.0]]),
                             np.array([1.0 + 0j]), np.array([10.0]), [{"tangential": np.array([1.0]),
                                                                        "kt": 1.0, "mu": 0.1, "n0": 1.0}])
    with pytest.raises(bladebench.InputError, match=r"stiffness: expected dtype float64 and shape \(1, 1\), "
                                                    r"got dtype float64 and shape \(2, 2\)"):
        bladebench.hbm_sweep(np.eye(1), np.eye(2), np.zeros((1, 1)), np.array([1.0 + 0j]), np.array([10.0]),
                             [{"tangential": np.array([1.0]), "kt": 1.0, "mu": 0.1, "n0": 1.0}])
    with pytest.raises(bladebench.InputError, match=r"force: expected dtype complex128 and shape \(1,\)"):
        bladebench.hbm_sweep(np.eye(1), np.eye(1), np.zeros((1, 1)), np.array([1.0]), np.array([10.0]),
                             [{"tangential": np.array([1.0]), "kt": 1.0, "mu": 0.1, "n0": 1.0}])
    with pytest.raises(bladebench.InputError, match=r"contacts\[0\]: unknown key 'k_t'"):
        bladebench.hbm_sweep(np.eye(1), np.eye(1), np.zeros((1, 1)), np.array([1.0 + 0j]), np.array([10.0]),
                             [{"tangential": np.array([1.0]), "k_t": 1.0, "mu": 0.1, "n0": 1.0}])


def test_a_model_is_held_to_what_the_case_reader_requires():
    """A zero, indefinite or asymmetric mass, negative damping, a contact value that is not a number:
    each refused as the case reader refuses it (issue 70: "converged" curves, or pybind11's cast error)."""
    def sweep(mass=np.eye(1), damping=np.zeros((1, 1)), kt=1.0e6, stiffness=None, n=1):
        return bladebench.hbm_sweep(mass, np.eye(n) * 1.0e6 if stiffness is None else stiffness, damping,
                                    np.ones(n, dtype=complex), np.array([150.0]),
                                    [{"tangential": np.eye(n)[0], "kt": kt, "mu": 0.3, "n0": 30.0}])
    with pytest.raises(bladebench.InputError, match=r"hbm_sweep: M is not positive definite"):
        sweep(mass=np.zeros((1, 1)))
    with pytest.raises(bladebench.InputError, match=r"hbm_sweep: M is not positive definite"):
        sweep(mass=-np.eye(1))
    with pytest.raises(bladebench.InputError, match=r"hbm_sweep: M is not symmetric"):
        sweep(mass=np.array([[1.0, 0.5], [0.0, 1.0]]), damping=np.zeros((2, 2)), n=2)
    with pytest.raises(bladebench.InputError, match=r"damping: must be positive semi-definite"):
        sweep(damping=-np.eye(1))
    with pytest.raises(bladebench.InputError, match=r"contacts\[0\]: 'kt': expected a number, found str"):
        sweep(kt="stiff")
    with pytest.raises(bladebench.InputError, match=r"contacts\[0\]: 'kt': 1e\+300 is out of range"):
        sweep(kt=1e300)


def test_errors_carry_the_command_lines_exit_classes_and_messages():
    assert issubclass(bladebench.InputError, ValueError) and bladebench.InputError.exit_code == 2
    assert issubclass(bladebench.SolverError, RuntimeError) and bladebench.SolverError.exit_code == 3
    bad = SOURCE / "tests/bad_input/modal_model_frequency_count.toml"
    with pytest.raises(bladebench.InputError, match=r"modal_model_frequency_count.toml:\d+: "
                                                    r"'analysis.model.frequency_hz': expected one frequency per DOF"):
        bladebench.run_case(str(bad))
    with pytest.raises(bladebench.InputError, match="unknown.key"):
        bladebench.run_case(CANTILEVER, settings=["unknown.key=1"])
    # A setting is one TOML value: more keys after a newline were dropped silently.
    with pytest.raises(bladebench.InputError, match="more than one TOML value"):
        bladebench.run_case(CANTILEVER, settings=["material.E=4.0e11\nmaterial.nu = 0.1"])
    # A contact law the harmonic balance refuses (negative stiffness) is bad input, not a crash.
    with pytest.raises(bladebench.InputError, match="kt"):
        oscillator(mu=0.3, force=1.0, frequencies=[150.0], kt=-1.0)


def test_calibrate_recovers_the_rig_contact_with_its_covariance():
    """The contact rig of jenkins_loop_identify: kt = 5e7 N/m, mu = 0.5, kn = 1e8 N/m wrote the loop."""
    fit = bladebench.calibrate(str(SOURCE / "cases/verification/jenkins_loop_identify.toml"))
    assert fit["converged"], fit["termination"]
    assert fit["parameters"] == ["analysis.contact.kt", "analysis.contact.mu", "analysis.contact.kn"]
    truth = np.array([5.0e7, 0.5, 1.0e8])
    sigma = fit["std_devs"]
    assert np.all(np.abs(fit["values"] - truth) < 4 * sigma), (fit["values"], sigma)
    cov = fit["covariance"]
    np.testing.assert_allclose(cov, cov.T, rtol=1e-12)
    np.testing.assert_allclose(np.diag(cov), sigma**2, rtol=1e-12)
    assert len(fit["starts"]) == 3 and fit["final_cost"] < fit["initial_cost"]
    points = fit["points"]
    assert isinstance(points, bladebench.Table) and points.shape[0] == 64
    assert set(points["set"]) == {"rig loop"}
    assert "hysteresis" in fit["curves"]
    assert "[analysis.contact]" in fit["calibrated_case"]


def test_calibrate_refuses_a_case_without_calibration_as_the_command_line_does():
    with pytest.raises(bladebench.InputError, match="calibration"):
        bladebench.calibrate(CANTILEVER)


def test_a_harwell_boeing_export_reads_into_matrices_with_its_dof_names():
    rom = bladebench.read_reduced_model(str(SOURCE / "cases/verification/data/hb_chain/chain.toml"))
    assert rom["dofs"] == [f"{n}.x" for n in range(101, 109)]
    k, m = rom["stiffness"], rom["mass"]
    np.testing.assert_array_equal(k, k.T)
    assert k[0, 0] == 4.0e6 and k[7, 7] == 2.0e6 and k[0, 1] == -2.0e6 and k[0, 2] == 0.0
    np.testing.assert_array_equal(m, 0.5 * np.eye(8))
    with pytest.raises(bladebench.InputError, match=r"short.mapping names 7 DOFs"):
        bladebench.read_reduced_model(str(SOURCE / "tests/bad_input/data/hb/short.toml"))


def law_sweep(contact, frequencies, force=5.0, harmonics=5):
    """The oscillator of oscillator() with any contact dict (kt = 1e6 N/m, n0 = 30 N)."""
    base = {"tangential": np.array([1.0]), "kt": 1.0e6, "mu": 0.3, "n0": 30.0}
    base.update(contact)
    return bladebench.hbm_sweep(
        mass=np.array([[1.0]]), stiffness=np.array([[1.0e6]]), damping=np.array([[10.0]]),
        force=np.array([force], dtype=complex), frequencies_hz=np.asarray(frequencies, dtype=float),
        contacts=[base], harmonics=harmonics)


def test_every_friction_law_reaches_the_sweep_and_meets_its_limits():
    f = np.arange(150.0, 231.0, 2.0)
    jenkins = law_sweep({}, f)
    assert jenkins["converged"].all()
    # Iwan with one slider and no macro-slip weight is the Jenkins element itself.
    one_slider = law_sweep({"law": "iwan", "chi": -0.5, "sliders": 1}, f)
    np.testing.assert_allclose(one_slider["amplitude"], jenkins["amplitude"], rtol=1e-9)
    # The coupled 2D law on a straight path (no motion along its second direction) is the 1D law.
    straight = law_sweep({"law": "coupled_slip", "tangential_2": np.array([0.0])}, f)
    np.testing.assert_allclose(straight["amplitude"], jenkins["amplitude"], rtol=1e-7)
    # Coulomb's law in the frequency domain is regularised by kt: the Jenkins law, as in the cases.
    coulomb = law_sweep({"law": "coulomb"}, f)
    np.testing.assert_allclose(coulomb["amplitude"], jenkins["amplitude"], rtol=1e-12)
    # A 32-slider Iwan joint slips gradually: its peak lies between the free and the stuck resonance.
    iwan = law_sweep({"law": "iwan", "chi": -0.5, "beta": 0.5, "sliders": 32}, f)
    assert iwan["converged"].all(), iwan["failures"]
    peak = f[np.argmax(iwan["amplitude"][:, 0])]
    assert math.sqrt(1.0e6) / (2 * math.pi) < peak < math.sqrt(2.0e6) / (2 * math.pi)


def test_a_law_s_keys_are_refused_where_they_do_not_belong():
    with pytest.raises(bladebench.InputError, match=r"contacts\[0\]: 'chi' belongs to law 'iwan'"):
        law_sweep({"chi": -0.5}, [160.0])
    with pytest.raises(bladebench.InputError, match="'tangential_2'"):
        law_sweep({"law": "coupled_slip"}, [160.0])
    with pytest.raises(bladebench.InputError, match="'law': 'bristle' is not one of"):
        law_sweep({"law": "bristle"}, [160.0])
    with pytest.raises(bladebench.InputError, match=r"'sliders': an integer"):
        law_sweep({"law": "iwan", "sliders": 2.5}, [160.0])


def reference_rows(path):
    rows = [line.strip().split(",") for line in open(path) if line.strip() and not line.startswith("#")]
    header = rows[0]
    return {name: np.array([float(r[k]) for r in rows[1:]]) for k, name in enumerate(header)}


def test_shooting_with_coulomb_s_rigid_stick_is_den_hartog_s_exact_motion():
    """1 kg on 1e6 N/m, 10 N, a Coulomb contact of 3 N (mu 0.3, n0 10 N): Den Hartog's exact
    non-stop motion (references/verification/coulomb_den_hartog.py), to the reference's 12 digits."""
    ref = reference_rows(SOURCE / "references/verification/coulomb_den_hartog.csv")
    pick = [0, 40, 100]
    out = bladebench.shooting_sweep(
        mass=np.array([[1.0]]), stiffness=np.array([[1.0e6]]), damping=np.array([[0.0]]),
        force=np.array([10.0 + 0j]), frequencies_hz=ref["frequency_hz"][pick],
        contacts=[{"tangential": np.array([1.0]), "kt": 1.0e6, "mu": 0.3, "n0": 10.0, "law": "coulomb"}],
        harmonics=3, steps_per_period=64, floquet=True)
    assert out["converged"].all(), out["failures"]
    np.testing.assert_allclose(out["largest"][:, 0], ref["max_m"][pick], rtol=1e-9)
    np.testing.assert_allclose(out["amplitude"][:, 0], ref["first_harmonic_m"][pick], rtol=1e-9)
    assert (out["transitions"] > 0).all() and out["stable"].all()


def test_shooting_agrees_with_the_harmonic_balance_and_refuses_a_law_without_a_flow():
    f = np.array([150.0, 175.0, 200.0])
    contact = {"tangential": np.array([1.0]), "kt": 1.0e6, "mu": 0.3, "n0": 30.0}
    args = dict(mass=np.array([[1.0]]), stiffness=np.array([[1.0e6]]), damping=np.array([[10.0]]),
                force=np.array([5.0 + 0j]), frequencies_hz=f)
    exact = bladebench.shooting_sweep(contacts=[contact], harmonics=5, **args)
    balance = bladebench.hbm_sweep(contacts=[contact], harmonics=15, **args)
    assert exact["converged"].all() and balance["converged"].all()
    np.testing.assert_allclose(exact["amplitude"], balance["amplitude"], rtol=1e-4)
    with pytest.raises(bladebench.InputError, match="coupled_slip.*use hbm_sweep"):
        bladebench.shooting_sweep(contacts=[dict(contact, law="coupled_slip", tangential_2=np.array([0.0]))], **args)


def test_a_nonlinear_mode_goes_from_the_stuck_to_the_sliding_oscillator():
    """1 kg on 1e6 N/m (c = 10 N s/m) with a Jenkins contact kt = 1e6 N/m, slip force 3 N: at small
    amplitude the stuck oscillator (k + kt, viscous ratio c / (2 m w)), at large amplitude the free
    one (k), and friction damping in between."""
    out = bladebench.nonlinear_modes(
        mass=np.array([[1.0]]), stiffness=np.array([[1.0e6]]), damping=np.array([[10.0]]),
        contacts=[{"tangential": np.array([1.0]), "kt": 1.0e6, "mu": 0.3, "n0": 10.0}],
        amplitudes=np.geomspace(1e-8, 1e-2, 25), harmonics=5)
    assert out["converged"], out["failure"]
    stuck, free = math.sqrt(2.0e6), math.sqrt(1.0e6)
    np.testing.assert_allclose(out["frequency_hz"][0], stuck / (2 * math.pi), rtol=1e-9)
    np.testing.assert_allclose(out["damping_ratio"][0], 10.0 / (2 * stuck), rtol=1e-6)
    assert abs(out["frequency_hz"][-1] / (free / (2 * math.pi)) - 1) < 2e-3
    assert out["damping_ratio"].max() > 10 * out["damping_ratio"][0]
    assert out["coefficients"].shape == (25, 1, 11)


def test_cyclic_modes_give_each_nodal_diameter_s_waves():
    """The 24-sector disk against CalculiX's cyclic symmetry on the same sector (the case's reference)."""
    disk = bladebench.cyclic_modes(str(SOURCE / "cases/beyond/bladed_disk_cyclic_modal.toml"))
    ccx = reference_rows(SOURCE / "references/verification/calculix_bladed_disk_cyclic.csv")
    assert disk["sectors"] == 24 and len(disk["diameters"]) == len(ccx["nodal_diameter"])
    for k, nd in enumerate(disk["diameters"]):
        assert nd["nodal_diameter"] == ccx["nodal_diameter"][k]
        np.testing.assert_allclose(nd["frequency_hz"][:2], [ccx["f1_hz"][k], ccx["f2_hz"][k]], rtol=1e-5)
        assert nd["cosine"].shape == (len(nd["frequency_hz"]), len(disk["node_ids"]), 3)
        if nd["nodal_diameter"] in (0, 12):
            assert not nd["sine"].any()
