"""python3-lammps drives the LAMMPS built with ACOUSTIC: a small granular deck,
a compute read back into numpy, and the package listed among the installed ones."""
import numpy as np
import pytest
from lammps import lammps, LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR, LMP_STYLE_ATOM, LMP_TYPE_VECTOR


@pytest.fixture
def lmp():
    instance = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    yield instance
    instance.close()


def test_package_is_installed(lmp):
    packages = lmp.installed_packages
    assert "GRANULAR" in packages
    assert "ACOUSTIC" in packages
    assert lmp.has_style("pair", "granular/acoustic")


def test_granular_deck_and_compute(lmp):
    lmp.commands_string("""
units lj
atom_style sphere
boundary p p fm
comm_modify vel yes
region box block 0 6 0 6 0 10
create_box 1 box
lattice sc 1.0
region fill block 0 6 0 6 0.5 6.5
create_atoms 1 region fill
displace_atoms all random 0.2 0.2 0.0 4451 units box
set group all diameter 0.95
set group all density 1.0
pair_style granular/acoustic
pair_coeff * * hooke 2e4 20 damping mass_velocity tangential linear_history 1e4 0.5 0.5
fix wall all wall/gran granular hooke 2e4 20 damping mass_velocity tangential linear_history 1e4 0.5 0.5 zplane 0.0 NULL
fix grav all gravity 10 vector 0.0 0.0 -1.0
fix nve all nve/sphere
compute contacts all contact/atom
compute ncontacts all reduce sum c_contacts
timestep 5e-4
thermo 0
run 3000
""")
    natoms = lmp.get_natoms()
    assert natoms == 216
    contacts = lmp.numpy.extract_compute("contacts", LMP_STYLE_ATOM, LMP_TYPE_VECTOR)
    total = lmp.extract_compute("ncontacts", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR)
    # a settled packing: every grain touches something, and the reduction equals the numpy sum
    assert total == pytest.approx(np.sum(contacts))
    assert np.mean(contacts) > 2.0
    # the layer rests on the wall: no grain below its radius, centre of mass low
    x = lmp.numpy.extract_atom("x")
    assert np.min(x[:, 2]) > 0.4
    assert np.mean(x[:, 2]) < 3.5
