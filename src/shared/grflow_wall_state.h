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
   What fix grflow/wall writes out, host-free: its output vector, its
   global restart data and the per-atom data that move with an atom
   (to another processor, into a restart file) (the walls: grflow_wall.h).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_STATE_H
#define LMP_GRFLOW_WALL_STATE_H

#include "grflow_host.h"
#include "grflow_wall.h"

#include <mpi.h>

#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  /* ----------------------------------------------------------------------
     the output vector: the walls' forces summed over the processors once
     per step (force_flag), then entry n (0-based); forces are extensive
  ------------------------------------------------------------------------- */

  static inline int wall_vector_extensive(int n)
  {
    return (n % FlatWalls::VEC_PER_WALL < 3) ? 1 : 0;
  }

  static inline double wall_vector_value(FlatWalls &cell, int n, MPI_Comm world)
  {
    typedef FlatWalls W;
    if (cell.force_flag == 0) {
      double local[W::NWALL * 3], total[W::NWALL * 3];
      for (int iw = 0; iw < W::NWALL; iw++)
        for (int k = 0; k < 3; k++) local[3 * iw + k] = cell.walls[iw].force[k];
      MPI_Allreduce(local, total, W::NWALL * 3, MPI_DOUBLE, MPI_SUM, world);
      for (int iw = 0; iw < W::NWALL; iw++)
        for (int k = 0; k < 3; k++) cell.wall_force_all[iw][k] = total[3 * iw + k];
      cell.force_flag = 1;
    }
    const int iw = n / W::VEC_PER_WALL, k = n % W::VEC_PER_WALL;
    const W::Wall &w = cell.walls[iw];
    if (k < 3) return cell.wall_force_all[iw][k];
    if (k == W::VEC_Z) return w.active ? w.z : 0.0;
    return w.disp[k - W::VEC_DX];
  }

  /* ----------------------------------------------------------------------
     global restart data (write_restart_block() and read_restart_block()
     around them): the walls' state; restoring it checks that the
     command has the walls of the file
  ------------------------------------------------------------------------- */

  static inline void pack_wall_state(const FlatWalls &cell, double *list)
  {
    int n = 0;
    for (const FlatWalls::Wall &w : cell.walls) {
      list[n++] = w.active;
      list[n++] = w.z;
      for (int k = 0; k < 3; k++) list[n++] = w.v[k];
      list[n++] = w.disp[0];
      list[n++] = w.disp[1];
    }
  }

  template <class Host>
  static void restore_wall_state(FlatWalls &cell, const char *buf, const char *id, Host &host)
  {
    typedef FlatWalls W;
    const std::string who = std::string("Fix grflow/wall ") + id;
    int version;
    const double *list =
        read_restart_block(who, buf, W::RESTART_VERSION, W::NRESTART, version, host);
    int n = 0;
    for (W::Wall &w : cell.walls) {
      const int active = (int) list[n++];
      if (active != w.active) {
        host.fail(FLERR, who + ": restart file has other walls than the command");
        return;
      }
      w.z = list[n++];
      for (int k = 0; k < 3; k++) w.v[k] = list[n++];
      w.disp[0] = list[n++];
      w.disp[1] = list[n++];
    }
  }

  /* ----------------------------------------------------------------------
     per-atom data (the host allocates history and contact with NHIST and
     NCONTACT columns)
  ------------------------------------------------------------------------- */

  // an atom whose wall histories came from elsewhere: no force-bearing
  // contact on record, but the next contact pass clears a history of a
  // wall it does not touch (rec: its NCONTACT values; active: the walls'
  // flags; also in device code)
  static GRFLOW_INLINE void mark_wall_records_unknown(const int *active, double *rec)
  {
    typedef FlatWalls W;
    for (int m = 0; m < W::NCONTACT; m++) rec[m] = 0.0;
    for (int w = 0; w < W::NWALL; w++)
      if (active[w]) rec[W::REC_SIZE * w + W::REC_ARM] = -1.0;
  }

  static inline void mark_wall_contacts_unknown(FlatWalls &cell, int i)
  {
    const int active[FlatWalls::NWALL] = {cell.walls[FlatWalls::LO].active,
                                          cell.walls[FlatWalls::HI].active};
    mark_wall_records_unknown(active, cell.contact[i]);
  }

  static inline void clear_wall_atom(FlatWalls &cell, int i)
  {
    for (int m = 0; m < FlatWalls::NHIST; m++) cell.history[i][m] = 0.0;
    for (int m = 0; m < FlatWalls::NCONTACT; m++) cell.contact[i][m] = 0.0;
  }

  static inline void copy_wall_atom(FlatWalls &cell, int i, int j)
  {
    for (int m = 0; m < FlatWalls::NHIST; m++) cell.history[j][m] = cell.history[i][m];
    for (int m = 0; m < FlatWalls::NCONTACT; m++) cell.contact[j][m] = cell.contact[i][m];
  }

  // an atom moving to another processor: its histories
  static inline int pack_wall_atom(const FlatWalls &cell, int i, double *buf)
  {
    for (int m = 0; m < FlatWalls::NHIST; m++) buf[m] = cell.history[i][m];
    return FlatWalls::NHIST;
  }

  static inline int unpack_wall_atom(FlatWalls &cell, int i, const double *buf)
  {
    for (int m = 0; m < FlatWalls::NHIST; m++) cell.history[i][m] = buf[m];
    mark_wall_contacts_unknown(cell, i);
    return FlatWalls::NHIST;
  }

  // the restart data of an atom: the count, then its histories
  static inline int pack_wall_atom_restart(const FlatWalls &cell, int i, double *buf)
  {
    buf[0] = FlatWalls::NRESTART_ATOM;
    for (int m = 0; m < FlatWalls::NHIST; m++) buf[m + 1] = cell.history[i][m];
    return FlatWalls::NRESTART_ATOM;
  }

  // extra: the atom's restart data of all fixes, this fix's the nth
  static inline void unpack_wall_atom_restart(FlatWalls &cell, int i, const double *extra, int nth)
  {
    int m = 0;
    for (int k = 0; k < nth; k++) m += static_cast<int>(extra[m]);
    m++;
    for (int k = 0; k < FlatWalls::NHIST; k++) cell.history[i][k] = extra[m++];
    mark_wall_contacts_unknown(cell, i);
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
