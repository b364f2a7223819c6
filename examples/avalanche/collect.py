#!/usr/bin/python3
"""Collect the ensembles of run_ensemble.sh into the tables and figures of RESULTS.md.

    /usr/bin/python3 examples/avalanche/collect.py [OUT_DIR] [FIG_DIR]

OUT_DIR (default examples/avalanche/out) holds ensemble_periodic/H<H>/s<seed>/,
ensemble/H<H>/s<seed>/ (free ends, 400 d), ensemble_L<length>/H<H>/s<seed>/
(free ends of another length) and ensemble_E<modulus>/..., ensemble_e<restitution>/...
(another contact law; AVALANCHE_EDEM, AVALANCHE_REST of run_ensemble.sh), each with log.deposit, log.f0,
log.f70 and the t_con runs log.tcon_f*_<theta> (log.tcon_f*_<theta>_u<hold>: the
same with another hold time of the uniform criterion).  Prints markdown tables:
packings, theta_m(H/d) per geometry with means and standard deviations, the
fitted slope of theta_m(H/d) with its standard error, the 70 kHz shift (paired
by packing), t_con (and against the hold time), the ramps of a packing at other drive frequencies
(log.f60 ...) beside its 0 and 70 kHz ramps; writes OUT_DIR/summary.json and
the figures fig7_thetam, fig8_tcon and, where the dumps and series are there (not in the record of
record.py), fig10_chains_H6, fig3_modes_H6, fig6_9_sigma_H14.4 and, with t_con runs of
another hold at 19 deg and H = 6 d, tcon_hold_sigma_H6 (sigma_l of the longest-held run); with the
runs of `run_production.sh build kappa` (OUT_DIR/kappa/k<kappa>/, periodic) and
`kappa_free` (OUT_DIR/kappa_free/k<kappa>/, free ends), the tables and the
figures kappa_shift and kappa_shift_free of the 70 kHz shift against
kappa_scale (PNG).
"""
import os
import sys

from acoustic_tools.avalanche_collect import collect

here = os.path.dirname(os.path.abspath(__file__))


def main(top=os.path.join(here, "out"), figdir=os.path.join(here, "figures")):
    collect(top, figdir)


if __name__ == "__main__":
    main(*sys.argv[1:])
