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

#include "citations_acoustic.h"

namespace LAMMPS_NS {
namespace AcousticCitations {

  const char two_time_scale_model[] =
      "ACOUSTIC package, ultrasound-induced friction reduction: J. Fluid Mech. 1004, A10 (2025)\n\n"
      "@Article{ultrasound-dense-granular-flows-2025,\n"
      " title =   {Ultrasound-induced dense granular flows: a two-time-scale modelling},\n"
      " journal = {Journal of Fluid Mechanics},\n"
      " year =    {2025},\n"
      " volume =  {1004},\n"
      " pages =   {A10}\n"
      "}\n\n";

  const char confined_wave_propagation[] =
      "ACOUSTIC package, vibration of granular contact networks: doi:10.1103/PhysRevE.72.021301\n\n"
      "@Article{somfai2005elastic,\n"
      " author =  {Somfai, Ell\\'ak and Roux, Jean-No\\\"el and Snoeijer, Jacco H. and\n"
      "            van Hecke, Martin and van Saarloos, Wim},\n"
      " title =   {Elastic wave propagation in confined granular systems},\n"
      " journal = {Physical Review E},\n"
      " year =    {2005},\n"
      " volume =  {72},\n"
      " pages =   {021301},\n"
      " doi =     {10.1103/PhysRevE.72.021301}\n"
      "}\n\n";

  const char wall_force_fluctuations[] =
      "ACOUSTIC package, grain-wall contacts of a sheared granular flow: "
      "doi:10.1103/PhysRevE.96.042906\n\n"
      "@Article{kneib2017force,\n"
      " author =  {Kneib, Fran\\c{c}ois and Faug, Thierry and Nicolet, Gilles and\n"
      "            Eckert, Nicolas and Naaim, Mohamed and Dufour, Fr\\'ed\\'eric},\n"
      " title =   {Force fluctuations on a wall in interaction with a granular\n"
      "            lid-driven cavity flow},\n"
      " journal = {Physical Review E},\n"
      " year =    {2017},\n"
      " volume =  {96},\n"
      " number =  {4},\n"
      " pages =   {042906},\n"
      " doi =     {10.1103/PhysRevE.96.042906}\n"
      "}\n\n";

}    // namespace AcousticCitations
}    // namespace LAMMPS_NS
