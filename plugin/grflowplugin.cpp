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
   Plugin entry point: registers the GRFLOW styles (pair granular/grflow,
   compute grflow/network, fix grflow/wall, fix grflow/shear,
   fix grflow/compress, fix grflow/drag, fix grflow/checksum) with a PLUGIN-enabled
   LAMMPS 4Feb2025 built with the same MPI, LAMMPS_SIZES and compiler.
     plugin load grflowplugin.so
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "compute_grflow_network.h"
#include "fix_grflow_checksum.h"
#include "fix_grflow_compress.h"
#include "fix_grflow_drag.h"
#include "fix_grflow_shear.h"
#include "fix_grflow_wall.h"
#include "pair_granular_grflow.h"

using namespace LAMMPS_NS;

static Pair *pair_granular_grflow_creator(LAMMPS *lmp)
{
  return new PairGranularGRFLOW(lmp);
}

static Compute *compute_grflow_network_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new ComputeGRFLOWNetwork(lmp, argc, argv);
}

static Fix *fix_grflow_wall_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixGRFLOWWall(lmp, argc, argv);
}

static Fix *fix_grflow_shear_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixGRFLOWShear(lmp, argc, argv);
}

static Fix *fix_grflow_checksum_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixGRFLOWChecksum(lmp, argc, argv);
}

static Fix *fix_grflow_compress_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixGRFLOWCompress(lmp, argc, argv);
}

static Fix *fix_grflow_drag_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixGRFLOWDrag(lmp, argc, argv);
}

extern "C" __attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle,
                                                                          void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;

  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "granular/grflow";
  plugin.info = "GRFLOW linear spring-dashpot contact with sliding, rolling and torsion";
  plugin.author = "GRFLOW developers";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_granular_grflow_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "grflow/network";
  plugin.info = "GRFLOW sub-volume stress, coordination, connectivity and fabric anisotropy";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &compute_grflow_network_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "grflow/wall";
  plugin.info = "GRFLOW flat frictional walls normal to z";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_grflow_wall_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "grflow/shear";
  plugin.info = "GRFLOW stress-controlled cyclic simple shear at constant height";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_grflow_shear_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "grflow/compress";
  plugin.info = "GRFLOW isotropic compression of the cell by all six sides, stress servo";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_grflow_compress_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "grflow/drag";
  plugin.info = "GRFLOW drag on velocities and spins (fix langevin at zero temperature)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_grflow_drag_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "grflow/checksum";
  plugin.info = "GRFLOW checksum file next to every restart file, once it is complete";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_grflow_checksum_creator;
  (*register_plugin)(&plugin, lmp);
}
