/* ----------------------------------------------------------------------
   ACOUSTIC package numerics: sparse symmetric LDL^T factorisation with
   MUMPS, on one or several MPI ranks.
------------------------------------------------------------------------- */

#include "acoustic_mumps_ldlt.h"

#include <dmumps_c.h>
#include <zmumps_c.h>

#include <cstdint>
#include <limits>
#include <string>

namespace Acoustic {

namespace {

enum MumpsJob { JOB_INIT = -1, JOB_END = -2, JOB_ANALYSE = 1, JOB_FACTORISE = 2, JOB_SOLVE = 3 };
const int RELEASE = -1;    // order: leave serve()

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

// ICNTL(k) and INFOG(k) with MUMPS's 1-based numbering
template <typename Struct> MUMPS_INT &icntl(Struct &s, int k)
{
  return s.icntl[k - 1];
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
  return "MUMPS error INFOG(1) = " + std::to_string(code) + ", INFOG(2) = " + std::to_string(detail) +
      " (" + what + ")";
}

}    // namespace

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

/* ---------------------------------------------------------------------- */

namespace {

template <typename Scalar> MumpsInstanceOf<Scalar> &instance_of(const std::unique_ptr<MumpsInstance> &p)
{
  return static_cast<MumpsInstanceOf<Scalar> &>(*p);
}

}    // namespace

template <typename Scalar> MumpsLdlt<Scalar>::MumpsLdlt(MumpsTeam &team) : instance_(new MumpsInstanceOf<Scalar>(team))
{
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
  m.run(JOB_ANALYSE);
  info_ = Eigen::Success;
  message_.clear();
  if (infog(m.data, 1) < 0) {
    info_ = Eigen::InvalidInput;
    message_ = mumps_error(infog(m.data, 1), infog(m.data, 2));
  }
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
  // work arrays too small (more delayed pivots than the analysis foresaw):
  // relax them and factorise again
  for (int attempt = 0;; ++attempt) {
    m.run(JOB_FACTORISE);
    const int code = infog(m.data, 1);
    if ((code == -8 || code == -9 || code == -14 || code == -15) && attempt < 6) {
      icntl(m.data, 14) = 2 * icntl(m.data, 14) + 20;
      continue;
    }
    break;
  }
  info_ = Eigen::Success;
  message_.clear();
  const int code = infog(m.data, 1);
  if (code < 0) {
    info_ = (code == -10) ? Eigen::NumericalIssue : Eigen::InvalidInput;
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

template class MumpsLdlt<double>;
template class MumpsLdlt<std::complex<double>>;

}    // namespace Acoustic
