/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing authors: the ACOUSTIC package developers.

   Vibration modes K v = omega^2 M v of the contact network of pair
   granular (the network fix acoustic/mindlin drives), with the
   atoms of a fixed group clamped: the network is gathered to rank 0 by
   VibrationNetwork, solved there by the ACOUSTIC numerics (dense, Lanczos
   or KPM), and the results are broadcast or scattered back.
------------------------------------------------------------------------- */

#include "compute_vibration_modes.h"

#include "citations_acoustic.h"
#include "citeme.h"

#include "acoustic_contact_network.h"
#include "acoustic_dynamical_matrix.h"
#include "acoustic_frequency_histogram.h"
#include "acoustic_solver_error.h"
#include "command_arguments.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "update.h"

#include <cmath>
#include <new>

using namespace LAMMPS_NS;

static const char CMD[] = "compute vibration/modes";
static constexpr int HISTOGRAM_COLUMNS = 3;    // bin centre, density, error of the density
static constexpr int MODE_COLUMNS = 3;         // mode index, frequency, participation ratio

/* ---------------------------------------------------------------------- */

ComputeVibrationModes::ComputeVibrationModes(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), method(Acoustic::ModeMethod::Dense), fixed_groupbit(0), nmodes(10),
    nbins(0), fmin(0.0), fmax(0.0), selected_mode(0), ndof(0), solved_step(-1),
    solved_with_shapes(false), nzero(0.0), histogram(nullptr), mode_rows(nullptr),
    nmode_rows_max(0), shape_atom(nullptr), nmax(0)
{
  if (lmp->citeme) lmp->citeme->add(AcousticCitations::two_time_scale_model);
  if (lmp->citeme) lmp->citeme->add(AcousticCitations::confined_wave_propagation);
  bool nmodes_set = false, kpm_set = false;
  CommandArguments args(lmp, CMD, narg, arg, 3);
  while (args.more()) {
    if (settings.parse(args, false)) continue;
    if (args.take("fixed", 1)) {
      fixed_group = args.group_name(1);
    } else if (args.take("method", 1)) {
      try {
        method = Acoustic::mode_method_from_name(args.word(1));
      } catch (Acoustic::SolverError &e) {
        args.reject(FLERR, 1, "{}", e.what());
      }
    } else if (args.take("nmodes", 1)) {
      nmodes = args.integer(1);
      if (nmodes <= 0) args.reject(FLERR, 1, "nmodes must be > 0, got {}", nmodes);
      nmodes_set = true;
    } else if (args.take("bins", 3)) {
      nbins = args.integer(1);
      fmin = args.number(2);
      fmax = args.number(3);
      try {
        Acoustic::check_histogram_range(nbins, fmin, fmax);
      } catch (Acoustic::SolverError &e) {
        args.reject(FLERR, 0, "bins Nb fmin fmax: {}", e.what());
      }
    } else if (args.take("mode", 1)) {
      selected_mode = args.integer(1);
      if (selected_mode < 1)
        args.reject(FLERR, 1,
                    "mode must be >= 1 (modes are numbered from 1 upwards in "
                    "frequency), got {}",
                    selected_mode);
    } else if (args.take("moments", 1)) {
      kpm.moments = args.integer(1);
      if (kpm.moments < 2) args.reject(FLERR, 1, "moments must be >= 2, got {}", kpm.moments);
      kpm_set = true;
    } else if (args.take("vectors", 1)) {
      kpm.random_vectors = args.integer(1);
      if (kpm.random_vectors < 2)
        args.reject(FLERR, 1, "vectors must be >= 2 (the error estimate needs two), got {}",
                    kpm.random_vectors);
      kpm_set = true;
    } else if (args.take("seed", 1)) {
      const bigint seed = args.big_integer(1);
      if (seed <= 0) args.reject(FLERR, 1, "seed must be > 0, got {}", seed);
      kpm.seed = static_cast<std::uint64_t>(seed);
      kpm_set = true;
    } else if (args.take("damping", 1)) {
      args.reject(FLERR, 0,
                  "keyword damping does not apply: the modes are those of the undamped "
                  "network (use damping with fix acoustic/mindlin)");
    } else {
      args.unknown("stiffness, kappa_scale, ratio, model, region_walls, fixed, method, nmodes, "
                   "bins, mode, moments, vectors, seed");
    }
    args.next();
  }

  // keywords that only one method uses
  const bool kpm_method = (method == Acoustic::ModeMethod::Kpm);
  if (nmodes_set && method != Acoustic::ModeMethod::Lanczos)
    error->all(FLERR,
               "{}: nmodes applies to method lanczos only (dense computes "
               "every mode); add method lanczos or remove nmodes",
               CMD);
  if (kpm_set && !kpm_method)
    error->all(FLERR, "{}: moments, vectors and seed apply to method kpm only", CMD);
  if (kpm_method && nbins == 0)
    error->all(FLERR,
               "{}: method kpm computes the density of states only; "
               "give its range with bins Nb fmin fmax",
               CMD);
  if (kpm_method && selected_mode > 0)
    error->all(FLERR,
               "{}: method kpm computes no individual mode; use method "
               "dense or lanczos with keyword mode",
               CMD);
  if (method == Acoustic::ModeMethod::Lanczos && selected_mode > nmodes)
    error->all(FLERR,
               "{}: mode {} is out of range: method lanczos computes "
               "nmodes = {} modes; raise nmodes to at least {}",
               CMD, selected_mode, nmodes, selected_mode);

  ndof = Acoustic::dofs_per_grain(domain->dimension, settings.model);
  network.reset(new VibrationNetwork(lmp, settings, CMD));
  // between runs the compute must know whether the system is still that of
  // the last run
  network->add_state_fix(id, group->names[igroup]);

  // outputs
  scalar_flag = 1;
  extscalar = 0;
  if (!kpm_method) {
    vector_flag = 1;
    size_vector = 0;
    size_vector_variable = 1;
    extvector = 0;
    local_flag = 1;
    size_local_rows = 0;
    size_local_cols = MODE_COLUMNS;
  }
  if (nbins > 0) {
    array_flag = 1;
    size_array_rows = nbins;
    size_array_cols = HISTOGRAM_COLUMNS;
    extarray = 0;
    memory->create(histogram, nbins, HISTOGRAM_COLUMNS, "vibration/modes:histogram");
    for (int b = 0; b < nbins; b++)
      for (int k = 0; k < HISTOGRAM_COLUMNS; k++) histogram[b][k] = 0.0;
    array = histogram;
  }
  size_peratom_cols = 0;
  if (selected_mode > 0) {
    peratom_flag = 1;
    size_peratom_cols = (settings.model == Acoustic::ContactModel::Full) ? 6 : 3;
  }
}

/* ---------------------------------------------------------------------- */

ComputeVibrationModes::~ComputeVibrationModes()
{
  if (network) network->delete_state_fix();
  memory->destroy(histogram);
  memory->destroy(mode_rows);
  memory->destroy(shape_atom);
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationModes::init()
{
  network->init();
  fixed_groupbit = 0;
  if (!fixed_group.empty()) {
    const int ifixed = group->find(fixed_group);
    if (ifixed < 0) error->all(FLERR, "{}: fixed group {} no longer exists", CMD, fixed_group);
    fixed_groupbit = group->bitmask[ifixed];
  }
  bigint counts_local[2] = {0, 0}, counts[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    counts_local[0]++;
    if (atom->mask[i] & fixed_groupbit) counts_local[1]++;
  }
  bigint outside_local = 0, outside = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & fixed_groupbit) && !(atom->mask[i] & groupbit)) outside_local++;
  MPI_Allreduce(counts_local, counts, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&outside_local, &outside, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (counts[0] == 0)
    error->all(FLERR, "{}: compute group {} has no atom", CMD, group->names[igroup]);
  if (fixed_groupbit && counts[1] == 0)
    error->all(FLERR,
               "{}: fixed group {} has no atom in the compute group {}; the clamped atoms "
               "must belong to the compute group",
               CMD, fixed_group, group->names[igroup]);
  if (outside > 0)
    error->all(FLERR,
               "{}: {} atoms of the fixed group {} are not in the compute group {}; the "
               "clamped atoms must all belong to the compute group",
               CMD, outside, fixed_group, group->names[igroup]);
  solved_step = -1;    // the packing may have changed since the last run
}

/* ----------------------------------------------------------------------
   rank 0: the eigenproblem of the network just built; returns an error
   message, empty on success
------------------------------------------------------------------------- */

std::string ComputeVibrationModes::solve_on_rank0(bool with_shapes)
{
  try {
    const Acoustic::ContactNetwork &net = network->network();
    std::vector<int> fixed_dofs;
    // the fixed atoms and the wall planes are clamped
    for (int g : network->marked_grains(0))
      for (int k = 0; k < ndof; k++) fixed_dofs.push_back(net.dof(g, k));
    for (int g : network->wall_nodes())
      for (int k = 0; k < ndof; k++) fixed_dofs.push_back(net.dof(g, k));
    const Acoustic::DynamicalMatrix dynamical(net.stiffness_matrix(), net.mass_diagonal(),
                                              fixed_dofs, ndof);
    if (dynamical.num_free() == 0)
      return fmt::format("every atom of the compute group {} is in the fixed group {}: no degree "
                         "of freedom is left",
                         group->names[igroup], fixed_group);

    Acoustic::VibrationModes modes;
    Acoustic::FrequencyHistogram hist;
    switch (method) {
      case Acoustic::ModeMethod::Dense:
        modes = Acoustic::dense_vibration_modes(dynamical, with_shapes);
        break;
      case Acoustic::ModeMethod::Lanczos:
        modes = Acoustic::lanczos_vibration_modes(dynamical, nmodes);
        break;
      case Acoustic::ModeMethod::Kpm:
        hist = Acoustic::kpm_frequency_histogram(dynamical, nbins, fmin, fmax, kpm);
        // KPM resolves no single eigenvalue: the zero modes it reports are the DOFs
        // without any stiffness (rattlers), not mechanisms of the connected network
        modes.zero_modes = static_cast<int>(dynamical.decoupled_free_dofs().size());
        break;
    }
    const int nfound = static_cast<int>(modes.frequencies.size());
    if (selected_mode > nfound)
      return fmt::format("mode {} is out of range: method {} found {} modes of the network ({} "
                         "free DOFs); choose mode between 1 and {}",
                         selected_mode, Acoustic::mode_method_name(method), nfound,
                         dynamical.num_free(), nfound);
    if (nbins > 0 && method != Acoustic::ModeMethod::Kpm)
      hist = Acoustic::frequency_histogram(modes.frequencies, nbins, fmin, fmax);

    nzero = modes.zero_modes;
    frequencies.assign(modes.frequencies.data(), modes.frequencies.data() + nfound);
    participation.assign(modes.participation_ratios.data(),
                         modes.participation_ratios.data() + modes.participation_ratios.size());
    for (int b = 0; b < nbins; b++) {
      histogram[b][0] = hist.bin_centres[b];
      histogram[b][1] = hist.density[b];
      histogram[b][2] = hist.density_error[b];
    }
    if (selected_mode > 0 && with_shapes) {
      // the sign of a mode is arbitrary: make its largest component positive
      selected_shape = modes.shapes.col(selected_mode - 1);
      Eigen::Index largest = 0;
      selected_shape.cwiseAbs().maxCoeff(&largest);
      if (selected_shape[largest] < 0.0) selected_shape = -selected_shape;
    }
  } catch (Acoustic::SolverError &e) {
    return e.what();
  } catch (std::bad_alloc &) {
    if (method == Acoustic::ModeMethod::Kpm)
      return fmt::format("out of memory in the kernel polynomial method ({} moments, {} vectors); "
                         "use fewer moments or vectors",
                         kpm.moments, kpm.random_vectors);
    return "out of memory in the eigensolver; use method lanczos or kpm for large networks";
  }
  return std::string();
}

/* ----------------------------------------------------------------------
   build the network and solve, once per timestep (twice if the shapes are
   needed after a dense solve without them)
------------------------------------------------------------------------- */

void ComputeVibrationModes::solve(bool need_shapes)
{
  network->require_current_state(fmt::format("{} {}", CMD, id));
  if (solved_step == update->ntimestep && (solved_with_shapes || !need_shapes)) return;
  const bool with_shapes = need_shapes || selected_mode > 0;

  network->build(groupbit, {fixed_groupbit});
  std::string failure;
  if (comm->me == 0) failure = solve_on_rank0(with_shapes);
  int length = static_cast<int>(failure.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  if (length > 0) {
    failure.resize(length);
    MPI_Bcast(&failure[0], length, MPI_CHAR, 0, world);
    error->all(FLERR, "{}: {}", CMD, failure);
  }

  int nfound = static_cast<int>(frequencies.size());
  MPI_Bcast(&nfound, 1, MPI_INT, 0, world);
  frequencies.resize(nfound);
  MPI_Bcast(frequencies.data(), nfound, MPI_DOUBLE, 0, world);
  MPI_Bcast(&nzero, 1, MPI_DOUBLE, 0, world);
  if (nbins > 0) MPI_Bcast(&histogram[0][0], nbins * HISTOGRAM_COLUMNS, MPI_DOUBLE, 0, world);

  solved_step = update->ntimestep;
  solved_with_shapes = with_shapes;
}

/* ----------------------------------------------------------------------
   length of the vector of frequencies this step (fix ave/time mode vector)
------------------------------------------------------------------------- */

int ComputeVibrationModes::lock_length()
{
  solve(false);
  return static_cast<int>(frequencies.size());
}

/* ---------------------------------------------------------------------- */

double ComputeVibrationModes::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  solve(false);
  scalar = nzero;
  return scalar;
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationModes::compute_vector()
{
  invoked_vector = update->ntimestep;
  solve(false);
  size_vector = static_cast<int>(frequencies.size());
  vector = frequencies.data();
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationModes::compute_array()
{
  invoked_array = update->ntimestep;
  solve(false);
}

/* ----------------------------------------------------------------------
   one row per mode on rank 0: mode index, frequency, participation ratio
------------------------------------------------------------------------- */

void ComputeVibrationModes::compute_local()
{
  invoked_local = update->ntimestep;
  solve(true);
  const int nrows = (comm->me == 0) ? static_cast<int>(participation.size()) : 0;
  if (nrows > nmode_rows_max) {
    nmode_rows_max = nrows;
    memory->destroy(mode_rows);
    memory->create(mode_rows, nmode_rows_max, MODE_COLUMNS, "vibration/modes:mode_rows");
  }
  for (int m = 0; m < nrows; m++) {
    mode_rows[m][0] = m + 1;
    mode_rows[m][1] = frequencies[m];
    mode_rows[m][2] = participation[m];
  }
  size_local_rows = nrows;
  array_local = mode_rows;
}

/* ----------------------------------------------------------------------
   shape of the selected mode: translations (x, y, z), then rotations
   (x, y, z) with model full; zero for fixed atoms and atoms not in the group
------------------------------------------------------------------------- */

void ComputeVibrationModes::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  solve(true);

  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(shape_atom);
    memory->create(shape_atom, nmax, size_peratom_cols, "vibration/modes:shape_atom");
    array_atom = shape_atom;
  }
  Eigen::VectorXd values;
  if (comm->me == 0) values = selected_shape;
  network->scatter_displacements(values, shape_atom, size_peratom_cols, groupbit);
}

/* ---------------------------------------------------------------------- */

double ComputeVibrationModes::memory_usage()
{
  double bytes = 0.0;
  if (peratom_flag) bytes += static_cast<double>(nmax) * size_peratom_cols * sizeof(double);
  bytes += static_cast<double>(frequencies.size() + participation.size()) * sizeof(double);
  bytes += static_cast<double>(nmode_rows_max) * MODE_COLUMNS * sizeof(double);
  bytes += static_cast<double>(selected_shape.size()) * sizeof(double);
  return bytes;
}
