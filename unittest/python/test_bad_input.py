"""Every bad input to the package's commands stops a batch run (lmp -in deck)
with an ERROR line that names the problem, on screen and in the log file, on 1
and on 2 MPI ranks; numbers of absurd size are refused or handled, never a
crash.  Each case is a real LAMMPS run of the executable built here."""
import os
import subprocess

import pytest

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")

# a 2D hexagonal layer of equal grains in contact on a row of base grains
LAYER = """
units lj
dimension 2
atom_style sphere
boundary p fm p
comm_modify vel yes
processors * 1 1
lattice hex 1.1547005383792517
region box block 0 10 0 5 -0.5 0.5
create_box 2 box
region base block INF INF -0.1 0.1 INF INF units box
region layer block INF INF 0.5 4.3 INF INF units box
create_atoms 2 region base
create_atoms 1 region layer
group base type 2
group grains type 1
group empty type 3
set group all diameter 1.002
set group all density 1.0
pair_style granular
pair_coeff * * hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5
fix plane all enforce2d
thermo 0
"""

FIX = "fix ac all acoustic/mindlin 10 frequency 0.5 amplitude 1e-3 source base"
COMPUTE = "compute m all vibration/modes fixed base"
TOP = "region upper block INF INF 3.0 INF INF INF units box\ngroup top region upper\n"
PULSE = TOP + "compute p all vibration/pulse source base detector top duration 20"
FLOOR = ("fix floor all wall/gran granular hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5 "
         "yplane -0.6 NULL\n")

# (name, lines after LAYER, expected part of the ERROR message)
BAD_INPUTS = [
    # fix acoustic/mindlin: arguments
    ("fix_too_few_args", "fix ac all acoustic/mindlin 10 frequency 5",
     "expected fix ID group-ID acoustic/mindlin N"),
    ("fix_bad_every", "fix ac all acoustic/mindlin 0 frequency 5 amplitude 1e-3 source base",
     "N must be > 0"),
    ("fix_misspelt_frequency", "fix ac all acoustic/mindlin 10 freq 5 amplitude 1e-3 source base",
     "expected 'frequency' as argument 5, got 'freq'"),
    ("fix_negative_frequency", "fix ac all acoustic/mindlin 10 frequency -5 amplitude 1e-3 source base",
     "frequency must be >= 0"),
    ("fix_infinite_frequency", "fix ac all acoustic/mindlin 10 frequency 1e400 amplitude 1e-3 source base",
     "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_frequency_not_a_number", "fix ac all acoustic/mindlin 10 frequency fast amplitude 1e-3 source base",
     "Expected floating point parameter instead of 'fast'"),
    ("fix_negative_amplitude", "fix ac all acoustic/mindlin 10 frequency 5 amplitude -1e-3 source base",
     "amplitude must be >= 0"),
    ("fix_infinite_amplitude", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e400 source base",
     "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_missing_source_group", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source floor",
     "source group floor does not exist"),
    ("fix_unknown_keyword", FIX + " loudness 3", "Unknown fix acoustic/mindlin keyword: loudness"),
    ("fix_keyword_without_value", FIX + " cmu", "Illegal fix acoustic/mindlin cmu command: missing argument(s)"),
    ("fix_zero_direction", FIX + " direction 0 0 0", "direction must not be the zero vector"),
    ("fix_infinite_direction", FIX + " direction 1e400 0 0",
     "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_direction_out_of_plane", FIX + " direction 0 1 1", "in 2D the direction must lie in the xy plane"),
    ("fix_bad_mode", FIX + " mode sideways", "mode must be 'all' or 'normal', got 'sideways'"),
    ("fix_mode_normal_oblique", FIX + " mode normal direction 1 1 0",
     "mode normal prescribes one Cartesian component"),
    ("fix_bad_stiffness", FIX + " stiffness spring", "stiffness must be 'pair' or 'hertz E nu'"),
    ("fix_stiffness_hertz_negative_E", FIX + " stiffness hertz -1 0.3", "needs Young's modulus E > 0"),
    ("fix_stiffness_hertz_bad_nu", FIX + " stiffness hertz 1e9 0.7", "needs -1 < nu < 0.5"),
    ("fix_stiffness_hertz_infinite_E", FIX + " stiffness hertz 1e400 0.3",
     "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_kappa_scale_zero", FIX + " kappa_scale 0", "kappa_scale must be in [1e-100, 1e100]"),
    ("fix_kappa_scale_huge", FIX + " kappa_scale 1e300", "kappa_scale must be in [1e-100, 1e100] (a factor on the Hertz constant), got 1e+300"),
    ("fix_kappa_scale_infinite", FIX + " kappa_scale 1e400", "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_negative_ratio", FIX + " ratio -1", "ratio k_t/k_n must be >= 0"),
    ("fix_infinite_ratio", FIX + " ratio 1e400", "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_negative_cmu", FIX + " cmu -1", "cmu must be >= 0"),
    ("fix_infinite_cmu", FIX + " cmu 1e400", "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_bad_mu_min", FIX + " mu_min 1.5", "mu_min must be in [0, 1]"),
    ("fix_bad_model", FIX + " model rigid", "unknown contact model 'rigid'"),
    ("fix_negative_damping", FIX + " damping -0.1", "damping ratio must be >= 0"),
    ("fix_infinite_damping", FIX + " damping 1e400", "Floating point number 1e400 in input script or data file is out of range"),
    ("fix_unknown_solver", FIX + " solver magic", "unknown linear solver 'magic'"),
    ("fix_ldlt_with_damping", FIX + " damping 0.1 solver ldlt", "solver ldlt handles undamped"),
    ("fix_bad_reuse", FIX + " reuse maybe", "Expected boolean parameter instead of 'maybe'"),
    ("fix_zero_tolerance", FIX + " solver iterative tolerance 0", "tolerance must be in (0, 1), got 0"),
    ("fix_tolerance_one", FIX + " solver iterative tolerance 1", "tolerance must be in (0, 1), got 1"),
    ("fix_zero_max_iterations", FIX + " solver iterative max_iterations 0",
     "max_iterations must be >= 1, got 0"),
    ("fix_unknown_preconditioner", FIX + " solver iterative preconditioner ilu",
     "unknown preconditioner 'ilu': allowed are none, shifted"),
    ("fix_negative_shift", FIX + " solver iterative shift -0.5", "shift must be >= 0, got -0.5"),
    ("fix_unknown_ordering", FIX + " ordering scotch", "ordering must be 'mumps' or 'metis', got 'scotch'"),
    ("fix_low_rank_one", FIX + " low_rank 1", "low_rank tolerance must be in [0, 1) (0: full rank), got 1"),
    # fix acoustic/mindlin: the system
    ("fix_empty_source", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source empty\nrun 0",
     "source group empty has no atom in the fix group all"),
    ("fix_source_outside_group",
     "fix ac grains acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base\nrun 0",
     "source group base has no atom in the fix group grains"),
    ("fix_source_partly_outside",
     "group halfbase id <= 5\ngroup sheet union grains halfbase\n"
     "fix ac sheet acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base\nrun 0",
     "atoms of the source group base are not in the fix group sheet"),
    ("fix_absurd_frequency", "fix ac all acoustic/mindlin 10 frequency 1e200 amplitude 1e-3 source base\nrun 0",
     "the frequency is out of range for this network"),
    ("fix_two_fixes", FIX + "\nfix ac2 grains acoustic/mindlin 10 frequency 1 amplitude 1e-3 source base\nrun 0",
     "would overwrite each other's friction factors"),
    ("fix_tangential_without_factor",
     "pair_coeff * * hooke 1e4 0 tangential linear_history 8e3 0 0.5\n" + FIX + "\nrun 0",
     "use tangential linear_history/acoustic in pair_coeff"),
    ("fix_not_pair_granular",
     "pair_style gran/hooke/history 1000 NULL 0.5 NULL 0.5 1\npair_coeff * *\n" + FIX + "\nrun 0",
     "requires pair_style granular with a tangential <model>/acoustic sub-model"),
    ("fix_coincident_atoms", "create_atoms 1 single 2 2 0 units box\ncreate_atoms 1 single 2 2 0 units box\n"
     "set group all diameter 1.002\nset group all density 1.0\n" + FIX + "\nrun 0",
     "are at the same position: their contact has no normal"),
    # compute vibration/modes
    ("compute_unknown_keyword", COMPUTE + " loudness 3", "Unknown compute vibration/modes keyword: loudness"),
    ("compute_region_walls_not_boolean", COMPUTE + " region_walls maybe", "Expected boolean parameter"),
    ("fix_region_source_without_direction",
     "region lid plane 0 -0.45 0 0 1 0 units box\n"
     "fix lid all wall/gran/region granular hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5 "
     "region lid\nfix ac all acoustic/mindlin 10 frequency 0.5 amplitude 1e-3 source wall lid\nrun 0",
     "give the direction of its drive"),
    ("compute_bad_method", COMPUTE + " method magic", "magic"),
    ("compute_nmodes_without_lanczos", COMPUTE + " nmodes 4", "nmodes applies to method lanczos only"),
    ("compute_zero_nmodes", COMPUTE + " method lanczos nmodes 0", "nmodes must be > 0"),
    ("compute_zero_mode", COMPUTE + " mode 0", "mode must be >= 1"),
    ("compute_too_many_bins", COMPUTE + " bins 2000000000 0 10",
     "2000000000 bins is more than the 1000000 a histogram may have"),
    ("compute_infinite_fmax", COMPUTE + " bins 10 0 1e400", "Floating point number 1e400 in input script or data file is out of range"),
    ("compute_bad_range", COMPUTE + " bins 10 5 1", "need 0 <= fmin < fmax"),
    ("compute_kpm_without_bins", COMPUTE + " method kpm", "give its range with bins Nb fmin fmax"),
    ("compute_few_moments", COMPUTE + " method kpm bins 10 0 10 moments 1", "moments must be >= 2"),
    ("compute_damping", COMPUTE + " damping 0.1", "keyword damping does not apply"),
    ("compute_missing_fixed_group", "compute m all vibration/modes fixed floor",
     "fixed group floor does not exist"),
    ("compute_fixed_partly_outside",
     "group halfbase id <= 5\ngroup sheet union grains halfbase\n"
     "compute m sheet vibration/modes fixed base\nthermo_style custom step c_m\nrun 0",
     "atoms of the fixed group base are not in the compute group sheet"),
    ("compute_everything_fixed",
     "compute m base vibration/modes fixed base\nthermo_style custom step c_m\nrun 0",
     "no degree of freedom is left"),
    ("compute_mode_beyond_the_modes",
     "group one id 1:12\ncompute m one vibration/modes mode 300\n"
     "dump d all custom 1 shape.dump id c_m[1]\nrun 0",
     "mode 300 is out of range"),
    # compute vibration/pulse
    ("pulse_missing_duration", TOP + "compute p all vibration/pulse source base detector top",
     "give the time to follow the pulse with duration T"),
    ("pulse_negative_duration", PULSE + " duration -1", "duration must be > 0 (time units), got -1"),
    ("pulse_infinite_duration", PULSE + " duration 1e400",
     "Floating point number 1e400 in input script or data file is out of range"),
    ("pulse_one_sample", PULSE + " samples 1", "samples must be in [2, 1e7], got 1"),
    ("pulse_zero_timestep", PULSE + " timestep 0", "timestep must be > 0, got 0"),
    ("pulse_snapshot_after_the_end", PULSE + " snapshot 30", "the snapshot time 30 is after the duration 20"),
    ("pulse_bad_initial", PULSE + " initial kick", "unknown initial condition 'kick': use velocity or displacement"),
    ("pulse_bad_method", PULSE + " method fast", "unknown pulse method 'fast': use modes or integrate"),
    ("pulse_modes_with_damping", PULSE + " method modes damping 0.1", "method modes needs an undamped network"),
    ("pulse_zero_direction", PULSE + " direction 0 0 0", "direction must not be the zero vector"),
    ("pulse_direction_out_of_plane", PULSE + " direction 0 0 1", "in 2D the direction must lie in the xy plane"),
    ("pulse_unknown_keyword", PULSE + " loudness 3", "Unknown compute vibration/pulse keyword: loudness"),
    ("pulse_missing_detector", "compute p all vibration/pulse source base duration 20",
     "got 'duration' where 'detector' belongs"),
    ("pulse_missing_group", "compute p all vibration/pulse source base detector roof duration 20",
     "detector group roof does not exist"),
    ("pulse_wall_without_id", "compute p all vibration/pulse source base detector wall",
     "Illegal compute vibration/pulse detector command: missing argument(s)"),
    ("pulse_wall_not_wall_gran", TOP + "compute p all vibration/pulse source wall plane detector top duration 20",
     "source wall plane is not a fix wall/gran"),
    ("pulse_same_wall", FLOOR + "compute p all vibration/pulse source wall floor detector wall floor "
     "duration 20\nrun 0", "the source and the detector are the same wall floor"),
    ("pulse_overlapping_groups", TOP + "compute p all vibration/pulse source all detector top duration 20\nrun 0",
     "atoms are in both the source group all and the detector group top"),
    ("pulse_source_not_in_group", TOP + "compute p grains vibration/pulse source base detector top duration 20\nrun 0",
     "source group base has no atom in the compute group grains"),
    ("pulse_source_partly_outside", TOP + "group halfbase id <= 5\ngroup sheet union grains halfbase\n"
     "compute p sheet vibration/pulse source base detector top duration 20\nrun 0",
     "atoms of the source group base are not in the compute group sheet"),
    ("pulse_deaf_detector", FLOOR + TOP + "compute p all vibration/pulse source top detector wall floor "
     "duration 20\nthermo_style custom step c_p[3]\nrun 0", "the detector touches no free grain"),
    ("pulse_unstable_timestep", PULSE + " method integrate timestep 100\nthermo_style custom step c_p[3]\nrun 0",
     "the integration could be unstable"),
    # lifecycle between runs: a compute evaluated after the system changed (issue: stale state)
    ("modes_after_displace_atoms", COMPUTE + "\nthermo_style custom step c_m\nrun 0\n"
     "displace_atoms grains move 0.01 0 0 units box\nprint \"$(c_m[1])\"",
     "the system changed since the last run"),
    ("modes_after_delete_atoms", COMPUTE + "\nthermo_style custom step c_m\nrun 0\n"
     "group gone id 30\ndelete_atoms group gone\nprint \"$(c_m[1])\"",
     "the system changed since the last run"),
    ("modes_after_pair_coeff", COMPUTE + "\nthermo_style custom step c_m\nrun 0\n"
     "pair_coeff * * hooke 1e6 0 tangential linear_history/acoustic 8e5 0 0.5\nprint \"$(c_m[1])\"",
     "the system changed since the last run"),
    ("modes_after_unfix_wall", FLOOR + COMPUTE + "\nthermo_style custom step c_m\nrun 0\n"
     "unfix floor\nprint \"$(c_m[1])\"", "the system changed since the last run"),
    ("pulse_after_unfix_wall", FLOOR + PULSE + "\nthermo_style custom step c_p[3]\nrun 0\nunfix floor\n"
     "print \"$(c_p[3])\"", "the system changed since the last run"),
    ("pulse_after_set_diameter", PULSE + "\nthermo_style custom step c_p[3]\nrun 0\n"
     "set group grains diameter 1.01\nprint \"$(c_p[3])\"", "the system changed since the last run"),
    ("modes_after_change_box", COMPUTE + "\nthermo_style custom step c_m\nrun 0\n"
     "change_box all x final 0 10.5 units box\nprint \"$(c_m[1])\"", "the system changed since the last run"),
    ("modes_after_pair_style", COMPUTE + "\nthermo_style custom step c_m\nrun 0\npair_style granular\n"
     "pair_coeff * * hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5\nprint \"$(c_m[1])\"",
     "the system changed since the last run"),
    # unbounded work in the pulse integration
    ("pulse_tiny_timestep", PULSE + " method integrate timestep 1e-12\nthermo_style custom step c_p[3]\nrun 0",
     "method integrate would take 2e+13 steps"),
    ("pulse_underflowing_timestep", PULSE + " method integrate timestep 1e-300\nthermo_style custom step c_p[3]\n"
     "run 0", "more than max_steps = 100000000"),
    ("pulse_huge_duration", TOP + "compute p all vibration/pulse source base detector top duration 1e300 "
     "method integrate\nthermo_style custom step c_p[3]\nrun 0", "more than max_steps"),
    ("pulse_bad_max_steps", PULSE + " max_steps 0", "max_steps must be in [1, 9e18], got 0"),
    ("compute_tangential_without_factor",
     "pair_coeff * * hooke 1e4 0 tangential linear_history 8e3 0 0.5\n" + COMPUTE +
     "\nthermo_style custom step c_m\nrun 0",
     "use tangential linear_history/acoustic in pair_coeff"),
]


def run_batch(tmp_path, deck, ranks):
    """lmp -in deck -log log.lammps on `ranks` MPI ranks; (returncode, screen, log)"""
    (tmp_path / "in.deck").write_text(LAYER + deck + "\n")
    command = [LMP, "-in", "in.deck", "-log", "log.lammps", "-nocite"]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "--oversubscribe"] + command
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=120)
    log = tmp_path / "log.lammps"
    return done.returncode, done.stdout + done.stderr, log.read_text() if log.exists() else ""


@pytest.mark.parametrize("ranks", [1, 2])
@pytest.mark.parametrize("name,deck,message", BAD_INPUTS, ids=[case[0] for case in BAD_INPUTS])
def test_error_reaches_the_log(tmp_path, name, deck, message, ranks):
    returncode, screen, log = run_batch(tmp_path, deck, ranks)
    assert returncode != 0, f"{name}: the run did not fail\n{screen}"
    error_lines = [line for line in log.splitlines() if line.startswith("ERROR")]
    assert error_lines, f"{name}: no ERROR line in the log file\nscreen:\n{screen}\nlog:\n{log}"
    assert message in error_lines[0], f"{name}: {error_lines[0]!r} does not say {message!r}"
    assert message in screen
    assert "MPI_ABORT" not in screen and "Signal" not in screen, screen


def factors_line(log):
    """the last thermo line: step, contacts, mean, min, weak fraction"""
    rows = [line.split() for line in log.splitlines()]
    rows = [r for r in rows if len(r) == 5 and r[0].isdigit()]
    return [float(v) for v in rows[-1]]


@pytest.mark.parametrize("ranks", [1, 2])
def test_huge_and_tiny_directions_are_the_diagonal(tmp_path, ranks):
    """direction 1e200 1e200 0 and 1e-200 1e-200 0 are the direction 1 1 0"""
    results = []
    for direction in ["1 1 0", "1e200 1e200 0", "1e-200 1e-200 0"]:
        deck = (FIX + f" direction {direction} solver lu\n"
                "thermo_style custom step f_ac[1] f_ac[2] f_ac[3] f_ac[4]\n"
                "thermo_modify format float %.15g\nrun 0")
        returncode, screen, log = run_batch(tmp_path, deck, ranks)
        assert returncode == 0, screen
        results.append(factors_line(log))
    assert results[0][2] < 1.0, "no friction reduction: the comparison would be empty"
    assert results[1] == results[0]
    assert results[2] == results[0]


@pytest.mark.parametrize("ranks", [1, 2])
def test_huge_amplitude_gives_the_smallest_factor(tmp_path, ranks):
    """U0 = 1e300: the tangential amplitudes overflow; the factors go to mu_min, no NaN"""
    deck = (FIX.replace("amplitude 1e-3", "amplitude 1e300") + " mu_min 0.2 cmu 1e300\n"
            "thermo_style custom step f_ac[1] f_ac[2] f_ac[3] f_ac[4]\nrun 0")
    returncode, screen, log = run_batch(tmp_path, deck, ranks)
    assert returncode == 0, screen
    step, contacts, mean, minimum, weak = factors_line(log)
    assert contacts > 50
    assert minimum == pytest.approx(0.2)
    assert 0.2 <= mean < 1.0


# (name, lines after LAYER, the word the ERROR must mark)
MARKED_WORDS = [
    ("fix_unknown_keyword", FIX + " loudness 3", "loudness"),
    ("fix_bad_value", FIX + " cmu -2", "-2"),
    ("fix_missing_source_group", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source floor", "floor"),
    ("compute_unknown_keyword", COMPUTE + " loudness 3", "loudness"),
    ("compute_bad_value", COMPUTE + " nmodes 0", "0"),
    ("pulse_unknown_keyword", PULSE + " loudness 3", "loudness"),
    ("pulse_bad_value", PULSE + " samples 1", "1"),
]


@pytest.mark.parametrize("name,deck,word", MARKED_WORDS, ids=[case[0] for case in MARKED_WORDS])
def test_error_marks_the_offending_word(tmp_path, name, deck, word):
    """LAMMPS's argument-pointer errors: the log echoes the command and puts
    carets under the word at fault."""
    returncode, screen, log = run_batch(tmp_path, deck, 1)
    assert returncode != 0, f"{name}: the run did not fail\n{screen}"
    lines = log.splitlines()
    echo = next(k for k, line in enumerate(lines) if line.startswith("Last input line: "))
    command, carets = lines[echo], lines[echo + 1]
    start = carets.index("^")
    assert carets.strip() == "^" * len(word), f"{name}: {carets!r}"
    assert command[start:start + len(word)] == word and command[start - 1] == " ", \
        f"{name}: the carets point at {command[start:start + len(word)]!r}, not {word!r}\n{command}\n{carets}"
