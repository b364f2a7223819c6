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
   Contributing authors: the ACOUSTIC package developers.
------------------------------------------------------------------------- */

#include "granular_state.h"

#include "atom.h"
#include "domain.h"
#include "fix.h"
#include "fix_wall_gran.h"
#include "fix_wall_gran_region.h"
#include "force.h"
#include "gran_sub_mod.h"
#include "granular_model.h"
#include "lammps.h"
#include "modify.h"
#include "pair_granular.h"
#include "region.h"
#include "utils.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace Granular_NS;

void Fingerprint::mix(std::uint64_t value)
{
  for (int byte = 0; byte < 8; byte++) {
    hash ^= (value >> (8 * byte)) & 0xff;
    hash *= 1099511628211ULL;
  }
}

void Fingerprint::mix(double value)
{
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof(bits));
  mix(bits);
}

void Fingerprint::mix(const std::string &text)
{
  for (unsigned char c : text) mix(static_cast<std::uint64_t>(c));
  mix(static_cast<std::uint64_t>(text.size()));
}

namespace {

void mix_model(Fingerprint &f, GranularModel *model)
{
  if (!model) return;
  for (auto *sub : model->sub_models) {
    if (!sub) continue;
    f.mix(sub->name);
    for (int k = 0; k < sub->num_coeffs; k++) f.mix(sub->coeffs[k]);
  }
}

void mix_atom_order(Fingerprint &f, Atom *atom)
{
  f.mix(static_cast<std::uint64_t>(atom->nlocal));
  f.mix(static_cast<std::uint64_t>(atom->nghost));
  for (int i = 0; i < atom->nlocal + atom->nghost; i++)
    f.mix(static_cast<std::uint64_t>(atom->tag[i]));
}

}    // namespace

std::uint64_t LAMMPS_NS::atom_order_fingerprint(LAMMPS *lmp)
{
  Fingerprint f;
  mix_atom_order(f, lmp->atom);
  return f.value();
}

std::uint64_t LAMMPS_NS::granular_state_fingerprint(LAMMPS *lmp)
{
  Fingerprint f;
  Atom *atom = lmp->atom;
  mix_atom_order(f, atom);
  for (int i = 0; i < atom->nlocal + atom->nghost; i++) {
    for (int k = 0; k < 3; k++) f.mix(atom->x[i][k]);
    if (atom->radius) f.mix(atom->radius[i]);
    if (atom->rmass) f.mix(atom->rmass[i]);
    f.mix(static_cast<std::uint64_t>(atom->mask[i]));
  }
  Domain *domain = lmp->domain;
  for (int k = 0; k < 3; k++) {
    f.mix(domain->boxlo[k]);
    f.mix(domain->boxhi[k]);
  }
  auto *pair = dynamic_cast<PairGranular *>(lmp->force->pair_match("granular", 1));
  f.mix(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(pair)));
  if (pair)
    for (int m = 0; m < pair->nmodels; m++) mix_model(f, pair->models_list[m]);
  for (auto *fix : lmp->modify->get_fix_list()) {
    if (!utils::strmatch(fix->style, "^wall/gran")) continue;
    f.mix(std::string(fix->id));
    f.mix(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(fix)));
    auto *wall = dynamic_cast<FixWallGran *>(fix);
    if (!wall) continue;
    mix_model(f, wall->model);
    int dim = 0;
    for (const char *name : {"lo", "hi"}) {
      const auto *value = static_cast<double *>(fix->extract(name, dim));
      if (value) f.mix(*value);
    }
    // the region of a wall/gran/region and where it has moved
    // (its pointer is read only while the region exists: a region deleted
    // between runs leaves the fix's pointer dangling until its next init())
    auto *region_wall = dynamic_cast<FixWallGranRegion *>(fix);
    if (!region_wall) continue;
    for (const Region *region : domain->get_region_list()) {
      if (region != region_wall->region) continue;
      f.mix(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(region)));
      for (double value : {region->dx, region->dy, region->dz, region->theta}) f.mix(value);
    }
  }
  return f.value();
}

bool LAMMPS_NS::same_on_every_rank(LAMMPS *lmp, std::uint64_t now, std::uint64_t recorded)
{
  int same = (now == recorded) ? 1 : 0, all = 0;
  MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, lmp->world);
  return all != 0;
}
