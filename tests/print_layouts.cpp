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
   The output layouts of GRFLOW's compute and fixes as the compiler sees
   them in the host-free headers (the one source of each), one line per
   entry: "layout name position" (0-based).  tests/python/test_layouts.py
   checks every other place that writes a layout out (inputs/names.lmp,
   inputs/walls.lmp, the series of inputs/shear.lmp, analysis/,
   tests/python/test_protocol.py, inputs/README.md) against these lines.
   An entry missing here is a compile error if it left the header; one
   moved in the header moves here.  The commands' classes use these
   layouts (compute_grflow_network.cpp, ...).
------------------------------------------------------------------------- */

#include "grflow_contact.h"
#include "grflow_network.h"
#include "grflow_servo.h"
#include "grflow_shear_rule.h"
#include "grflow_wall.h"

#include <cstdio>

using namespace LAMMPS_NS;

#define ENTRY(layout, cls, name) std::printf("%s %s %d\n", layout, #name, (int) cls::name)

int main()
{
  using Net = GRFLOW::NetworkLayout;
  ENTRY("network", Net, SXX);
  ENTRY("network", Net, SYY);
  ENTRY("network", Net, SZZ);
  ENTRY("network", Net, SXY);
  ENTRY("network", Net, SXZ);
  ENTRY("network", Net, SYZ);
  ENTRY("network", Net, PRESS);
  ENTRY("network", Net, TAU);
  ENTRY("network", Net, QDEV);
  ENTRY("network", Net, SNORM);
  ENTRY("network", Net, RU);
  ENTRY("network", Net, NP);
  ENTRY("network", Net, NFLOAT);
  ENTRY("network", Net, NCONTACT);
  ENTRY("network", Net, ZG);
  ENTRY("network", Net, ZPLAIN);
  ENTRY("network", Net, AC);
  ENTRY("network", Net, SC);
  ENTRY("network", Net, AXX);
  ENTRY("network", Net, AYY);
  ENTRY("network", Net, AZZ);
  ENTRY("network", Net, AXY);
  ENTRY("network", Net, AXZ);
  ENTRY("network", Net, AYZ);
  ENTRY("network", Net, VOLUME);
  ENTRY("network", Net, PC0);
  // the default cmax of the compute (the decks' P_c assume it)
  std::printf("network CMAX %d\n", GRFLOW::NetworkOptions().cmax);
  std::printf("network SIZE %d\n", Net::size(GRFLOW::NetworkOptions().cmax));

  using Shear = GRFLOW::ShearLayout;
  ENTRY("shear", Shear, DIRECTION);
  ENTRY("shear", Shear, REVERSALS);
  ENTRY("shear", Shear, XWALL);
  ENTRY("shear", Shear, GAMMA);
  ENTRY("shear", Shear, TAU);
  ENTRY("shear", Shear, PRESS);
  ENTRY("shear", Shear, RU);
  ENTRY("shear", Shear, P0);
  ENTRY("shear", Shear, STEP_IL);
  ENTRY("shear", Shear, TIME_IL);
  ENTRY("shear", Shear, N_IL);
  ENTRY("shear", Shear, N_EVENT);
  ENTRY("shear", Shear, DONE);
  ENTRY("shear", Shear, EVENT);
  ENTRY("shear", Shear, NOUT);

  using Comp = GRFLOW::CompressLayout;
  ENTRY("compress", Comp, CONVERGED);
  ENTRY("compress", Comp, SXX);
  ENTRY("compress", Comp, SYY);
  ENTRY("compress", Comp, SZZ);
  ENTRY("compress", Comp, ERRMAX);
  ENTRY("compress", Comp, KE);
  ENTRY("compress", Comp, EEL);
  ENTRY("compress", Comp, RATIO);
  ENTRY("compress", Comp, RATE_X);
  ENTRY("compress", Comp, RATE_Y);
  ENTRY("compress", Comp, RATE_Z);
  ENTRY("compress", Comp, VOLUME);
  ENTRY("compress", Comp, VOID);
  ENTRY("compress", Comp, LX);
  ENTRY("compress", Comp, LY);
  ENTRY("compress", Comp, HEIGHT);
  ENTRY("compress", Comp, FACTOR_X);
  ENTRY("compress", Comp, FACTOR_Y);
  ENTRY("compress", Comp, FACTOR_Z);
  ENTRY("compress", Comp, NOUT);

  // the extra values of pair granular/grflow's single() (compute pair/local p1 ...)
  using Single = GRFLOW::SingleLayout;
  ENTRY("single", Single, FS_X);
  ENTRY("single", Single, FS_Y);
  ENTRY("single", Single, FS_Z);
  ENTRY("single", Single, FS_LEN);
  ENTRY("single", Single, FR_X);
  ENTRY("single", Single, FR_Y);
  ENTRY("single", Single, FR_Z);
  ENTRY("single", Single, FR_LEN);
  ENTRY("single", Single, TWIST);
  ENTRY("single", Single, DX);
  ENTRY("single", Single, DY);
  ENTRY("single", Single, DZ);
  ENTRY("single", Single, FO);
  ENTRY("single", Single, FO_LEN);
  ENTRY("single", Single, FN);
  ENTRY("single", Single, NVALUES);

  using Wall = GRFLOW::FlatWalls;
  ENTRY("wall", Wall, LO_FX);
  ENTRY("wall", Wall, LO_FY);
  ENTRY("wall", Wall, LO_FZ);
  ENTRY("wall", Wall, LO_Z);
  ENTRY("wall", Wall, LO_DX);
  ENTRY("wall", Wall, LO_DY);
  ENTRY("wall", Wall, HI_FX);
  ENTRY("wall", Wall, HI_FY);
  ENTRY("wall", Wall, HI_FZ);
  ENTRY("wall", Wall, HI_Z);
  ENTRY("wall", Wall, HI_DX);
  ENTRY("wall", Wall, HI_DY);
  ENTRY("wall", Wall, NVECTOR);
  return 0;
}
