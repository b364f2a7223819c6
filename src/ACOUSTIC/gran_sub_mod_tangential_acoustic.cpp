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

#include "gran_sub_mod_tangential_acoustic.h"

#include "citations_acoustic.h"
#include "citeme.h"

#include "granular_model.h"

using namespace LAMMPS_NS;
using namespace Granular_NS;

/* ----------------------------------------------------------------------
   the wrapped model's history, then the factor
------------------------------------------------------------------------- */

template <class Model>
GranSubModTangentialAcoustic<Model>::GranSubModTangentialAcoustic(GranularModel *gm, LAMMPS *lmp) :
    Model(gm, lmp), model_size_history(this->size_history)
{
  if (lmp->citeme) lmp->citeme->add(AcousticCitations::two_time_scale_model);
  // fix wall/gran and wall/gran/region set their model's contact type before
  // they read its sub-models
  if (lmp->citeme && gm->contact_type != PAIR)
    lmp->citeme->add(AcousticCitations::wall_force_fluctuations);
  // the wrapped model's transfer factors (-1 by default: a tangential
  // displacement changes sign between i and j), +1 for the factor
  auto *factors = new double[model_size_history + 1];
  for (int i = 0; i < model_size_history; i++)
    factors[i] = this->nondefault_history_transfer ? this->transfer_history_factor[i] : -1.0;
  factors[model_size_history] = 1.0;
  delete[] this->transfer_history_factor;
  this->transfer_history_factor = factors;
  this->nondefault_history_transfer = 1;
  this->size_history = model_size_history + 1;
}

/* ----------------------------------------------------------------------
   the Coulomb limit of the wrapped model's calculate_forces(): s mu F_n,crit
------------------------------------------------------------------------- */

template <class Model> double GranSubModTangentialAcoustic<Model>::coulomb_mu() const
{
  return this->mu * friction_factor(&this->gm->history[friction_factor_index()]);
}

/* ---------------------------------------------------------------------- */

template <class Model> int GranSubModTangentialAcoustic<Model>::friction_factor_index() const
{
  return this->history_index + model_size_history;
}

/* ---------------------------------------------------------------------- */

template <class Model>
double GranSubModTangentialAcoustic<Model>::tangential_stiffness(double contact_radius) const
{
  return this->contact_radius_flag ? this->k * contact_radius : this->k;
}

namespace LAMMPS_NS {
namespace Granular_NS {
  template class GranSubModTangentialAcoustic<GranSubModTangentialLinearNoHistory>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialLinearHistory>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialLinearHistoryClassic>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinClassic>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialMindlin>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinForce>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinRescale>;
  template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinRescaleForce>;
}    // namespace Granular_NS
}    // namespace LAMMPS_NS
