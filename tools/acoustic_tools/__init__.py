"""ACOUSTIC's Python tools: readers of LAMMPS's outputs, the analysis of the
examples' runs, their tables and figures (numpy, scipy, matplotlib).

Readers
  lammps_log             thermo blocks and wall time of a LAMMPS log
  lammps_output          dumps, fix ave/time and ave/chunk files, "name value" files
  stats                  ensemble statistics (mean, standard deviation, count)

Avalanches on an inclined plane (paper 000, examples/avalanche)
  avalanche              sigma_l, E_k/E_t, the stability test, t_con, theta_m,
                         the spectrum of the contact network
  avalanche_figures      the figures of paper 000
  avalanche_study        the jobs of the study (job.json), their runner, the record,
                         the command line of examples/avalanche/study.py
  avalanche_collect      the jobs' JSON into tables and figures
  avalanche_calibration  the calibration scan through LAMMPS's Python module
  avalanche_snapshots    the network under the drive at paper 000's times (Figs. 10, 12, 13)
  avalanche_fields       the motion at an angle, reduced for the record (Figs. 6/9, 14)

Sound in confined packings (paper 003, examples/sound)
  sound                  the coherent peak, speeds, exponents, Table I statics
  network_moduli         C22 and C33 from the linear response of the contact network
  packing_checks         the acceptance checks run by examples/sound/in.packing
  sound_figures          the figures of paper 003
  sound_collect          the jobs of the study (job.json, result.json) into tables and figures
  sound_study            examples/sound/study.py: run, collect, figures, migrate

Granular lid-driven cavity (paper 004, examples/cavity)
  cavity                 inertial number, vortex centre, correlation times, Eq. 5 and 7 fits,
                         zero forces, stationarity, the local mu(I)
  cavity_figures         the figures of paper 004
  cavity_collect         the runs of the study (job.json, result.json) into tables and figures
  cavity_study           examples/cavity/study.py: plan, run (as restartable pieces), collect, figures

The modules with a command line run as `python3 -m acoustic_tools.MODULE`
(avalanche, avalanche_figures, lammps_log, packing_checks).
"""
