#!/usr/bin/python3
"""One-off: convert the record of the old layout (logs' result lines under
<set>/H<H>/s<seed>/log.*) into job directories with job.json and result.json
(acoustic_tools.avalanche_study's layout), so that collect reads only JSON.
The settings come from the old directory names and the result lines; this
script is the only reader of either, and is removed after its one use.

    /usr/bin/python3 examples/avalanche/migrate_record.py OLD_RECORD NEW_RECORD
"""
import glob
import json
import os
import re
import sys

from acoustic_tools import study
from acoustic_tools.avalanche_study import (deposit_settings, job_name, packing_settings, ramp_settings,
                                            tcon_settings)
from acoustic_tools.lammps_log import wall_time

HEADER = re.compile(r"avalanche \S+: (\d+) grains, (\d+) base grains, freq \S+ Hz, U0/d \S+, kappa_scale (\S+), "
                    r"source (\w+)")
LAW = re.compile(r"contact law Edem \S+ Pa, restitution \S+, time step (\S+) s")
SETTLED = re.compile(r"\((at rest|NOT at rest after tsettle|no pre-ramp)\)")
ANGLE = re.compile(r"^angle +([0-9.]+) deg: (\w+) after ([0-9.]+) s  max E_k/E_t (\S+)  max mobile fraction (\S+)  "
                   r"sigma1 (\S+) sigma2 (\S+)  mean mu\*/mu ([0-9.]+)")
RESULT = re.compile(r"theta_m = ([0-9.]+|none) deg\s+t_con = ([-0-9.]+) s")
DEPOSIT = re.compile(r"deposit: (\d+) grains on (\d+) base grains, box ([0-9.]+) d long, layer H = ([0-9.]+) d")
SET = re.compile(r"(?:ensemble(?:_L(\d+))?(?:_E([0-9.e+]+))?(?:_e([0-9.]+))?|ensemble_periodic|kappa/k([0-9.]+)"
                 r"|kappa_free/k([0-9.]+)|switch_on/at([0-9.]+)(?:_k([0-9.]+))?)")


def ramp_result(log, tag):
    text = open(log).read()
    header = HEADER.search(text)
    law = LAW.search(text)
    settled = SETTLED.search(text)
    result = RESULT.search(text)
    angles = [{"theta": float(m[1]), "state": m[2], "time": float(m[3]), "max_ratio": float(m[4]),
               "max_mobile": float(m[5]), "sigma1": float(m[6]), "sigma2": float(m[7]), "mu": float(m[8])}
              for m in map(ANGLE.match, text.splitlines()) if m]
    found = result and result[1] != "none"
    return {"tag": tag, "grains": int(header[1]), "base": int(header[2]),
            "dt": float(law[1]) if law else None, "settled": settled[1] if settled else "",
            "theta_m": float(result[1]) if found else None, "t_con": float(result[2]) if found else None,
            "angles": angles, "wall_time": wall_time(log)}, float(header[3]), header[4]


def write(dest, settings, result, extra=None):
    d = os.path.join(dest, job_name(settings))
    assert not os.path.exists(os.path.join(d, study.RESULT)), d
    study.write_job(d, settings)
    with open(os.path.join(d, study.RESULT), "w") as f:
        json.dump(result, f, indent=1)
        f.write("\n")
    for name, value in (extra or {}).items():
        with open(os.path.join(d, name), "w") as f:
            json.dump(value, f, indent=1)
            f.write("\n")
    return d


def main(old, dest):
    deposits = {}
    for path in sorted(glob.glob(os.path.join(old, "**", "H*", "s*"), recursive=True)):
        rel = os.path.relpath(path, old)
        set_dir, h, s = rel.rsplit("/", 2)
        m = SET.fullmatch(set_dir)
        assert m, set_dir
        layer, modulus, restitution, kappa_p, kappa_f, on, on_kappa = m.groups()
        free = 0 if set_dir == "ensemble_periodic" or kappa_p else 1
        H, seed = float(h[1:]), int(s[1:])
        packing = packing_settings(H, seed, free=free, layer=float(layer) if layer else None,
                                   Edem=float(modulus) if modulus else None,
                                   rest=float(restitution) if restitution else None)
        dep = DEPOSIT.search(open(os.path.join(path, "log.deposit")).read())
        dep_result = {"grains": int(dep[1]), "base": int(dep[2]), "length": float(dep[3]),
                      "H_measured": float(dep[4]), "wall_time": wall_time(os.path.join(path, "log.deposit"))}
        dsettings = dict(deposit_settings(packing), recorded_from=f"{rel}/log.deposit")
        name = job_name(dsettings)
        if name in deposits:      # the same packing deposited again by a study: the same numbers
            same = {k: v for k, v in dep_result.items() if k != "wall_time"}
            assert same == {k: v for k, v in deposits[name].items() if k != "wall_time"}, (rel, name)
        else:
            deposits[name] = dep_result
            write(dest, dsettings, dep_result)
        for log in sorted(glob.glob(os.path.join(path, "log.f*"))):
            tag = os.path.basename(log)[len("log."):]
            result, kappa, source = ramp_result(log, tag)
            freq = float(tag[1:]) * 1e3
            result.update(freq=freq, kappa=kappa)
            switch = float(on) if on else None
            settings = ramp_settings(packing, freq, kappa=kappa, source=source, theta0=result["angles"][0]["theta"]
                                     if not switch else None, switch_on=switch)
            if switch:
                settings["theta0"] = float(f"{switch + 0.5:.2f}")
            assert float(kappa_p or kappa_f or on_kappa or 0.3) == kappa, (log, kappa)
            settings["recorded_from"] = os.path.relpath(log, old)
            extra = {}
            if switch:
                quiet, _, _ = ramp_result(os.path.join(path, "log.quiet"), "quiet")
                quiet.update(freq=0.0, kappa=kappa)
                extra["quiet.json"] = quiet
            write(dest, settings, result, extra)
        for log in sorted(glob.glob(os.path.join(path, "log.tcon_*"))):
            tag = os.path.basename(log)[len("log."):]
            m = re.fullmatch(r"tcon_(f[0-9]+)_([0-9.]+)(?:_u([0-9.e-]+))?", tag)
            ramp_tag, theta, hold = m[1], float(m[2]), float(m[3]) if m[3] else None
            result, kappa, source = ramp_result(log, tag)
            freq = float(ramp_tag[1:]) * 1e3
            result.update(freq=freq, kappa=kappa)
            ramp = ramp_settings(packing, freq, kappa=kappa, source=source)
            settings = tcon_settings(ramp, theta, hold)
            assert settings["tag"] == tag, (settings["tag"], tag)
            settings["recorded_from"] = os.path.relpath(log, old)
            write(dest, settings, result)


if __name__ == "__main__":
    main(*sys.argv[1:])
