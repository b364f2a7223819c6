/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   ACOUSTIC package numerics: sparse symmetric LDL^T factorisation with
   MUMPS, on one or several MPI ranks.
------------------------------------------------------------------------- */

#include "acoustic_mumps_ldlt.h"

#include "acoustic_solver_error.h"

#ifdef ACOUSTIC_HAVE_MUMPS
#include <dmumps_c.h>
#include <zmumps_c.h>

#ifdef ACOUSTIC_HAVE_METIS
#include <metis.h>
#endif
#endif

#include <cstdint>
#include <limits>
#include <string>

namespace Acoustic {

namespace {

  const int RELEASE = -1;    // order: leave serve()

}    // namespace

#ifdef ACOUSTIC_HAVE_MUMPS
namespace {

  enum MumpsJob { JOB_INIT = -1, JOB_END = -2, JOB_ANALYSE = 1, JOB_FACTORISE = 2, JOB_SOLVE = 3 };

  // MUMPS's C structures and entry points per scalar type
  template <typename Scalar> struct MumpsApi;
  template <> struct MumpsApi<double> {
    typedef DMUMPS_STRUC_C Struct;
    typedef double Entry;
    static void call(Struct *s) { dmumps_c(s); }
  };
  template <> struct MumpsApi<std::complex<double>> {
    typedef ZMUMPS_STRUC_C Struct;
    typedef mumps_double_complex Entry;    // same layout as std::complex<double>
    static void call(Struct *s) { zmumps_c(s); }
  };

  // ICNTL(k), CNTL(k) and INFOG(k) with MUMPS's 1-based numbering
  template <typename Struct> MUMPS_INT &icntl(Struct &s, int k)
  {
    return s.icntl[k - 1];
  }
  template <typename Struct> auto &cntl(Struct &s, int k)
  {
    return s.cntl[k - 1];
  }
  template <typename Struct> MUMPS_INT infog(const Struct &s, int k)
  {
    return s.infog[k - 1];
  }

  std::string mumps_error(int code, int detail)
  {
    std::string what;
    switch (code) {
      case -5:
      case -7:
      case -13:
        what = "not enough memory";
        break;
      case -8:
      case -9:
      case -14:
      case -15:
        what = "internal work arrays too small";
        break;
      case -10:
        what = "numerically singular matrix";
        break;
      default:
        what = "see the MUMPS user guide";
        break;
    }
    return "MUMPS error INFOG(1) = " + std::to_string(code) +
        ", INFOG(2) = " + std::to_string(detail) + " (" + what + ")";
  }

  // The pivot order of a symmetric matrix (lower triangle given as 1-based
  // rows and columns, diagonal included) by METIS's nested dissection:
  // position (1-based) of each variable, as MUMPS's PERM_IN wants it.
  std::vector<int> nested_dissection_order(int n, const std::vector<int> &rows,
                                           const std::vector<int> &cols)
  {
#ifdef ACOUSTIC_HAVE_METIS
    // the adjacency of the graph (both directions, no self loops), in CSR
    std::vector<idx_t> degree(n + 1, 0);
    for (std::size_t k = 0; k < rows.size(); ++k)
      if (rows[k] != cols[k]) {
        ++degree[rows[k]];
        ++degree[cols[k]];
      }
    std::vector<idx_t> xadj(n + 1, 0);
    for (int v = 0; v < n; ++v) xadj[v + 1] = xadj[v] + degree[v + 1];
    std::vector<idx_t> fill(xadj.begin(), xadj.end() - 1), adjncy(xadj[n]);
    for (std::size_t k = 0; k < rows.size(); ++k)
      if (rows[k] != cols[k]) {
        adjncy[fill[rows[k] - 1]++] = cols[k] - 1;
        adjncy[fill[cols[k] - 1]++] = rows[k] - 1;
      }
    idx_t nvertices = n;
    std::vector<idx_t> perm(n), iperm(n);
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const int status = METIS_NodeND(&nvertices, xadj.data(), adjncy.data(), nullptr, options,
                                    perm.data(), iperm.data());
    if (status != METIS_OK)
      throw SolverError("METIS_NodeND failed (status " + std::to_string(status) + ")");
    std::vector<int> position(n);
    for (int v = 0; v < n; ++v) position[v] = static_cast<int>(iperm[v]) + 1;
    return position;
#else
    (void) n;
    (void) rows;
    (void) cols;
    throw SolverError("the METIS ordering needs an ACOUSTIC package built with METIS");
#endif
  }

}    // namespace
#endif

bool mumps_available()
{
#ifdef ACOUSTIC_HAVE_MUMPS
  return true;
#else
  return false;
#endif
}

MumpsOrdering mumps_ordering_from_name(const std::string &name)
{
  if (name == "auto") return MumpsOrdering::Auto;
  if (name == "metis") return MumpsOrdering::Metis;
  throw SolverError("unknown ordering '" + name + "': allowed are auto, metis");
}

std::string mumps_ordering_name(MumpsOrdering ordering)
{
  return ordering == MumpsOrdering::Metis ? "metis" : "auto";
}

bool metis_available()
{
#ifdef ACOUSTIC_HAVE_METIS
  return true;
#else
  return false;
#endif
}

/* ---------------------------------------------------------------------- */

// One MUMPS instance of a team; the host's calls are sent to the other ranks.
class MumpsInstance {
 public:
  explicit MumpsInstance(MumpsTeam &team) : team_(team) { number_ = team.attach(this); }
  virtual ~MumpsInstance() { team_.detach(number_); }
  // run a MUMPS job on this rank (workers: as ordered by the host)
  virtual void call(int job) = 0;
  // host: order the job to the other ranks, then run it here
  void run(int job)
  {
    if (team_.size() > 1) team_.order(number_, job);
    call(job);
  }
  MumpsTeam &team() { return team_; }

 private:
  MumpsTeam &team_;
  int number_;
};

#ifdef ACOUSTIC_HAVE_MUMPS
template <typename Scalar> class MumpsInstanceOf : public MumpsInstance {
 public:
  typedef MumpsApi<Scalar> Api;
  explicit MumpsInstanceOf(MumpsTeam &team) : MumpsInstance(team) { data = typename Api::Struct(); }
  ~MumpsInstanceOf() override
  {
    // collective: every rank of the team destroys its instances in the same order
    if (initialised) call(JOB_END);
  }
  void call(int job) override
  {
    if (job == JOB_INIT) {
      data.sym = 2;    // general symmetric: LDL^T with 1x1 and 2x2 pivots
      data.par = 1;    // the host factorises too
      data.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(team().comm()));
    }
    data.job = job;
    Api::call(&data);
    if (job == JOB_INIT) {
      initialised = true;
      icntl(data, 1) = -1;    // no error, diagnostic or global output: the caller reports
      icntl(data, 2) = -1;
      icntl(data, 3) = -1;
      icntl(data, 4) = 0;
      // MUMPS's automatic choice of the fill-reducing ordering: on contact
      // networks it takes nested dissection (PORD), which in 3D needs 40 %
      // fewer flops than the local orderings (AMD, AMF)
      icntl(data, 7) = 7;
    }
    if (job == JOB_END) initialised = false;
  }
  typename Api::Struct data;
  bool initialised = false;
};

#endif

/* ---------------------------------------------------------------------- */

MumpsTeam::MumpsTeam(MPI_Comm comm)
{
  MPI_Comm_dup(comm, &comm_);
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

MumpsTeam::~MumpsTeam()
{
  MPI_Comm_free(&comm_);
}

int MumpsTeam::attach(MumpsInstance *instance)
{
  instances_.push_back(instance);
  return static_cast<int>(instances_.size()) - 1;
}

void MumpsTeam::detach(int number)
{
  instances_[number] = nullptr;
}

void MumpsTeam::order(int number, int job)
{
  int message[2] = {number, job};
  MPI_Bcast(message, 2, MPI_INT, 0, comm_);
}

void MumpsTeam::serve()
{
  if (host() || size_ == 1) return;
  for (;;) {
    int message[2];
    MPI_Bcast(message, 2, MPI_INT, 0, comm_);
    if (message[0] == RELEASE) return;
    instances_[message[0]]->call(message[1]);
  }
}

void MumpsTeam::release()
{
  if (!host() || size_ == 1) return;
  int message[2] = {RELEASE, 0};
  MPI_Bcast(message, 2, MPI_INT, 0, comm_);
}

#ifdef ACOUSTIC_HAVE_MUMPS
/* ---------------------------------------------------------------------- */

namespace {

  template <typename Scalar>
  MumpsInstanceOf<Scalar> &instance_of(const std::unique_ptr<MumpsInstance> &p)
  {
    return static_cast<MumpsInstanceOf<Scalar> &>(*p);
  }

}    // namespace

template <typename Scalar>
MumpsLdlt<Scalar>::MumpsLdlt(MumpsTeam &team, const MumpsSettings &settings) :
    settings_(settings), instance_(new MumpsInstanceOf<Scalar>(team))
{
  if (settings.ordering == MumpsOrdering::Metis && !metis_available())
    throw SolverError("MUMPS ordering metis: this build of the ACOUSTIC package has no METIS "
                      "(Debian: libmetis-dev); use ordering auto");
  if (settings.low_rank &&
      !(settings.low_rank_tolerance > 0.0 && settings.low_rank_tolerance < 1.0))
    throw SolverError("MUMPS block low-rank tolerance must be in (0, 1), got " +
                      std::to_string(settings.low_rank_tolerance));
}

template <typename Scalar> MumpsLdlt<Scalar>::~MumpsLdlt() = default;

template <typename Scalar> void MumpsLdlt<Scalar>::analyzePattern(const MatrixType &a)
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  if (!m.team().host()) {
    info_ = Eigen::InvalidInput;
    message_ = "MumpsLdlt: only the host rank analyses";
    return;
  }
  if (!m.initialised) m.run(JOB_INIT);
  rows_.clear();
  cols_.clear();
  values_.clear();
  for (Eigen::Index col = 0; col < a.outerSize(); ++col)
    for (typename MatrixType::InnerIterator it(a, col); it; ++it)
      if (it.row() >= col) {
        rows_.push_back(static_cast<int>(it.row()) + 1);
        cols_.push_back(static_cast<int>(col) + 1);
        values_.push_back(it.value());    // the analysis may use them (pivot order)
      }
  m.data.n = static_cast<MUMPS_INT>(a.rows());
  m.data.nnz = static_cast<MUMPS_INT8>(rows_.size());
  m.data.nz = static_cast<MUMPS_INT>(rows_.size());
  m.data.irn = rows_.data();
  m.data.jcn = cols_.data();
  m.data.a = reinterpret_cast<typename MumpsApi<Scalar>::Entry *>(values_.data());
  if (settings_.ordering == MumpsOrdering::Metis) {
    pivot_order_ = nested_dissection_order(static_cast<int>(a.rows()), rows_, cols_);
    m.data.perm_in = pivot_order_.data();
    icntl(m.data, 7) = 1;    // the pivot order given in PERM_IN
  } else {
    icntl(m.data, 7) = 7;
  }
  // block low-rank factors (set before the analysis), compressed to CNTL(7)
  icntl(m.data, 35) = settings_.low_rank ? 2 : 0;
  cntl(m.data, 7) = settings_.low_rank ? settings_.low_rank_tolerance : 0.0;
  m.run(JOB_ANALYSE);
  take_status(false);
}

template <typename Scalar> void MumpsLdlt<Scalar>::factorize(const MatrixType &a)
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  if (!m.team().host()) {
    info_ = Eigen::InvalidInput;
    message_ = "MumpsLdlt: only the host rank factorises";
    return;
  }
  std::size_t k = 0;
  for (Eigen::Index col = 0; col < a.outerSize(); ++col)
    for (typename MatrixType::InnerIterator it(a, col); it; ++it)
      if (it.row() >= col) {
        if (k < values_.size()) values_[k] = it.value();
        ++k;
      }
  if (!m.initialised || k != values_.size() || a.rows() != m.data.n) {
    info_ = Eigen::InvalidInput;
    message_ = "MumpsLdlt: factorize() needs a matrix with the pattern given to analyzePattern()";
    return;
  }
  m.data.a = reinterpret_cast<typename MumpsApi<Scalar>::Entry *>(values_.data());
  factorise(false);
}

// The numeric factorisation, ordered by the host to the team (everyone
// false) or called by every rank (distributed input); work arrays too small
// (more delayed pivots than the analysis foresaw) are relaxed and the
// factorisation run again.
template <typename Scalar> void MumpsLdlt<Scalar>::factorise(bool everyone)
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  for (int attempt = 0;; ++attempt) {
    if (everyone)
      m.call(JOB_FACTORISE);
    else
      m.run(JOB_FACTORISE);
    const int code = infog(m.data, 1);
    if ((code == -8 || code == -9 || code == -14 || code == -15) && attempt < 6) {
      icntl(m.data, 14) = 2 * icntl(m.data, 14) + 20;
      continue;
    }
    break;
  }
  take_status(true);
}

// info() and message() from INFOG(1) and INFOG(2) of the last job
template <typename Scalar> void MumpsLdlt<Scalar>::take_status(bool factorisation)
{
  const MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  info_ = Eigen::Success;
  message_.clear();
  const int code = infog(m.data, 1);
  if (code < 0) {
    info_ = (factorisation && code == -10) ? Eigen::NumericalIssue : Eigen::InvalidInput;
    message_ = mumps_error(code, infog(m.data, 2));
  }
}

template <typename Scalar> void MumpsLdlt<Scalar>::solve_in_place(Dense &x) const
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  if (!m.team().host() || info_ != Eigen::Success || !m.initialised || x.rows() != m.data.n) {
    x.setConstant(Scalar(std::numeric_limits<double>::quiet_NaN()));
    return;
  }
  if (x.cols() == 0) return;
  m.data.rhs = reinterpret_cast<typename MumpsApi<Scalar>::Entry *>(x.data());
  m.data.nrhs = static_cast<MUMPS_INT>(x.cols());
  m.data.lrhs = static_cast<MUMPS_INT>(x.rows());
  m.run(JOB_SOLVE);
  if (infog(m.data, 1) < 0) x.setConstant(Scalar(std::numeric_limits<double>::quiet_NaN()));
}

/* ----------------------------------------------------------------------
   distributed assembled input: every rank calls MUMPS itself
------------------------------------------------------------------------- */

template <typename Scalar>
void MumpsLdlt<Scalar>::analyze_distributed(long n, const std::vector<long> &rows,
                                            const std::vector<long> &cols,
                                            const std::vector<Scalar> &values)
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  if (!m.initialised) m.call(JOB_INIT);
  rows_.resize(rows.size());
  cols_.resize(cols.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    rows_[k] = static_cast<int>(rows[k]) + 1;
    cols_[k] = static_cast<int>(cols[k]) + 1;
  }
  values_ = values;
  m.data.n = static_cast<MUMPS_INT>(n);
  icntl(m.data, 18) = 3;    // each rank its entries, for the analysis and the factorisation
  icntl(m.data, 20) = 0;    // dense right-hand side, on the host
  icntl(m.data, 21) = 0;    // solution on the host
  icntl(m.data, 7) = 7;     // MUMPS's own ordering
  icntl(m.data, 35) = settings_.low_rank ? 2 : 0;
  cntl(m.data, 7) = settings_.low_rank ? settings_.low_rank_tolerance : 0.0;
  m.data.nnz_loc = static_cast<MUMPS_INT8>(rows_.size());
  m.data.nz_loc = static_cast<MUMPS_INT>(rows_.size());
  m.data.irn_loc = rows_.data();
  m.data.jcn_loc = cols_.data();
  m.data.a_loc = reinterpret_cast<typename MumpsApi<Scalar>::Entry *>(values_.data());
  m.call(JOB_ANALYSE);
  take_status(false);
}

template <typename Scalar>
void MumpsLdlt<Scalar>::factorize_distributed(const std::vector<Scalar> &values)
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  if (!m.initialised || values.size() != values_.size()) {
    info_ = Eigen::InvalidInput;
    message_ =
        "MumpsLdlt: factorize_distributed() needs the entries given to analyze_distributed()";
    return;
  }
  values_ = values;
  m.data.a_loc = reinterpret_cast<typename MumpsApi<Scalar>::Entry *>(values_.data());
  factorise(true);
}

template <typename Scalar> void MumpsLdlt<Scalar>::solve_distributed(Dense &x) const
{
  MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  const bool host = m.team().host();
  int usable = (info_ == Eigen::Success && m.initialised && (!host || x.rows() == m.data.n)) ? 1
                                                                                             : 0;
  MPI_Allreduce(MPI_IN_PLACE, &usable, 1, MPI_INT, MPI_MIN, m.team().comm());
  if (!usable) {
    if (host) x.setConstant(Scalar(std::numeric_limits<double>::quiet_NaN()));
    return;
  }
  int columns = host ? static_cast<int>(x.cols()) : 0;
  MPI_Bcast(&columns, 1, MPI_INT, 0, m.team().comm());
  if (columns == 0) return;
  if (host) {
    m.data.rhs = reinterpret_cast<typename MumpsApi<Scalar>::Entry *>(x.data());
    m.data.lrhs = static_cast<MUMPS_INT>(x.rows());
  }
  m.data.nrhs = static_cast<MUMPS_INT>(columns);
  m.call(JOB_SOLVE);
  if (host && infog(m.data, 1) < 0) x.setConstant(Scalar(std::numeric_limits<double>::quiet_NaN()));
}

template <typename Scalar> long MumpsLdlt<Scalar>::factor_entries() const
{
  const MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  const long entries = infog(m.data, 29);
  return entries < 0 ? -entries * 1000000L : entries;    // negative: millions
}

template <typename Scalar> double MumpsLdlt<Scalar>::local_factorisation_flops() const
{
  const MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  return m.initialised ? static_cast<double>(m.data.rinfo[2]) : 0.0;    // RINFO(3)
}

template <typename Scalar> double MumpsLdlt<Scalar>::factorisation_flops() const
{
  const MumpsInstanceOf<Scalar> &m = instance_of<Scalar>(instance_);
  if (!m.initialised) return 0.0;
  // RINFOG(14): the operations done with low-rank blocks; RINFOG(3): full rank
  return settings_.low_rank ? static_cast<double>(m.data.rinfog[13])
                            : static_cast<double>(m.data.rinfog[2]);
}

#else    // no MUMPS: the solver says so when asked for

template <typename Scalar>
MumpsLdlt<Scalar>::MumpsLdlt(MumpsTeam &, const MumpsSettings &settings) : settings_(settings)
{
  throw SolverError("MUMPS: this build of the ACOUSTIC package has no MUMPS (Debian: "
                    "libmumps-dev; CMake: ACOUSTIC_WITH_MUMPS=on); use solver lu or ldlt, or "
                    "iterative for damped networks");
}
template <typename Scalar> MumpsLdlt<Scalar>::~MumpsLdlt() = default;
template <typename Scalar> void MumpsLdlt<Scalar>::analyzePattern(const MatrixType &) {}
template <typename Scalar> void MumpsLdlt<Scalar>::factorize(const MatrixType &) {}
template <typename Scalar> void MumpsLdlt<Scalar>::factorise(bool) {}
template <typename Scalar> void MumpsLdlt<Scalar>::take_status(bool) {}
template <typename Scalar> void MumpsLdlt<Scalar>::solve_in_place(Dense &) const {}
template <typename Scalar>
void MumpsLdlt<Scalar>::analyze_distributed(long, const std::vector<long> &,
                                            const std::vector<long> &, const std::vector<Scalar> &)
{
}
template <typename Scalar>
void MumpsLdlt<Scalar>::factorize_distributed(const std::vector<Scalar> &)
{
}
template <typename Scalar> void MumpsLdlt<Scalar>::solve_distributed(Dense &) const {}
template <typename Scalar> long MumpsLdlt<Scalar>::factor_entries() const
{
  return 0;
}
template <typename Scalar> double MumpsLdlt<Scalar>::local_factorisation_flops() const
{
  return 0.0;
}
template <typename Scalar> double MumpsLdlt<Scalar>::factorisation_flops() const
{
  return 0.0;
}

#endif

template class MumpsLdlt<double>;
template class MumpsLdlt<std::complex<double>>;

}    // namespace Acoustic
