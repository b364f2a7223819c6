"""citeme: a run that uses the package's styles lists the papers they
implement, in LAMMPS's citation file (-cite) and its screen summary."""
import os
import subprocess

from hex_layer import hex_layer

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")

DECK = hex_layer(6, 4, 3.3) + """
region upper block INF INF 2.5 INF INF INF units box
group top region upper
pair_style granular
pair_coeff * * hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5
fix plane all enforce2d
"""

USES = {
    "pair only": "run 0\n",
    "fix": "fix ac all acoustic/mindlin 10 frequency 0.5 amplitude 1e-3 source base\nrun 0\n",
    "pulse": "compute p all vibration/pulse source base detector top duration 5\n"
             "thermo_style custom step c_p[1]\nrun 0\n",
    "wall": "fix wall all wall/gran granular hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5 "
            "yplane NULL 3.5\nrun 0\n",
}

MODEL = "Ultrasound-induced dense granular flows: a two-time-scale modelling"
WAVES = "Elastic wave propagation in confined granular systems"
WALL = "Force fluctuations on a wall in interaction with a granular"


def cited(tmp_path, name, lines):
    (tmp_path / f"in.{name}").write_text(DECK + lines)
    done = subprocess.run([LMP, "-in", f"in.{name}", "-log", "none", "-cite", f"cite.{name}"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    return (tmp_path / f"cite.{name}").read_text()


def test_each_style_cites_the_papers_it_implements(tmp_path):
    pair = cited(tmp_path, "pair", USES["pair only"])
    assert MODEL in pair and WAVES not in pair     # the /acoustic sub-model
    assert WALL not in pair
    assert "Journal of Fluid Mechanics" in pair and "1004" in pair
    pulse = cited(tmp_path, "pulse", USES["pulse"])
    assert WAVES in pulse and "10.1103/PhysRevE.72.021301" in pulse
    fix = cited(tmp_path, "fix", USES["fix"])
    assert fix.count(MODEL) == 1                 # once, however many styles cite it
    wall = cited(tmp_path, "wall", USES["wall"])   # the sub-model on a wall/gran
    assert WALL in wall and "10.1103/PhysRevE.96.042906" in wall and "Kneib" in wall
    assert wall.count(MODEL) == 1
