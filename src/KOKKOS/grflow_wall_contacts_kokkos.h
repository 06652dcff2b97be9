/* -*- c++ -*- ----------------------------------------------------------
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
   Contributing authors: GRFLOW developers

   What a fix offers as extract("grflow/wall_contacts/kk") (fix
   grflow/wall/kk), for compute grflow/network/kk: the wall contacts of
   extract("grflow/wall_contacts") with the records where the fix keeps
   them on the Kokkos device, per atom nwall records of
   WallContacts::REC_SIZE values.  The interface between the two
   commands: neither includes the other's header.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_CONTACTS_KOKKOS_H
#define LMP_GRFLOW_WALL_CONTACTS_KOKKOS_H

#include "kokkos_type.h"

namespace LAMMPS_NS {
namespace GRFLOW {
  struct WallContacts;

  struct WallContactsKokkos {
    const WallContacts *contacts;    // nwall, normals, step (its host rows not synced)
    DAT::tdual_float_2d *records;
  };
}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
