/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: what the contact model (normal_model_grflow.h)
   tells the other GRFLOW classes of a LIGGGHTS run (compute
   grflow/network), in one place.

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_LIGGGHTS_H
#define LMP_GRFLOW_LIGGGHTS_H

#include "grflow_contact.h"

#include <map>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
namespace GRFLOW {

  // the layout of the model's part of a contact's history: the kernel's
  // springs (HIST_SIZE values), then the step of the last evaluation that
  // touched
  enum { LIGGGHTS_STAMP = HIST_SIZE, LIGGGHTS_HISTORY };

  // the springs of a contact as the law uses them on step `step`: zero if
  // the contact did not touch on the step before (LIGGGHTS keeps the
  // history of a listed pair that parted: a new touch is a new contact).
  // At the setup of a run (no history update) a touching contact
  // continues the springs it has, whatever their step: after read_restart
  // the history is that of the last neighbor list build before the file
  // was written (LIGGGHTS's restart command writes it so), and its stamp
  // is that step; the setup moves the stamp to the current step.
  static inline void current_springs(double *stored, double step, bool setup, double *hist)
  {
    if (setup && stored[LIGGGHTS_STAMP] < step) stored[LIGGGHTS_STAMP] = step;
    const bool fresh = stored[LIGGGHTS_STAMP] < step - 1.0;
    for (int k = 0; k < HIST_SIZE; k++) hist[k] = fresh ? 0.0 : stored[k];
  }

  // the pair style's contact law of a LIGGGHTS instance, published by
  // "pair_style gran model grflow" for compute grflow/network: the checked
  // coefficients of each type pair (index itype * (ntypes + 1) + jtype)
  // and where the model's values start in a pair's contact history
  struct LiggghtsPairLaw {
    const std::vector<ContactCoeffs> *coeff;
    int ntypes;
    int history_offset;
  };

  inline std::map<const LAMMPS *, LiggghtsPairLaw> &liggghts_pair_laws()
  {
    static std::map<const LAMMPS *, LiggghtsPairLaw> laws;
    return laws;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
