/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: the GRFLOW contact law as a LIGGGHTS contact
   model, "pair_style gran model grflow" and "fix wall/gran model grflow".

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   The law (linear spring-dashpot normal force, sliding, rolling and
   torsion springs with Coulomb caps; doc/pair_granular_grflow.rst) is
   computed by the host-free kernel grflow_contact.h, the same code that
   LAMMPS's pair_style granular/grflow runs.  This class is the LIGGGHTS
   glue: coefficients from fix property/global, the kernel's seven spring
   values in LIGGGHTS's contact history, the forces into ForceData.  The
   kernel gives all four modes at once, so the model stands alone: the
   tangential, rolling_friction and cohesion models must stay off (their
   default), and anything else is an error.  Doc: doc/liggghts_gran_model_grflow.rst
------------------------------------------------------------------------- */

#ifdef NORMAL_MODEL
// clang-format off
NORMAL_MODEL(NORMAL_GRFLOW,grflow,20)
// clang-format on
#else
#ifndef NORMAL_MODEL_GRFLOW_H_
#define NORMAL_MODEL_GRFLOW_H_

#include "contact_models.h"
#include "global_properties.h"
#include "normal_model_base.h"

#include "grflow_coeff_rules.h"
#include "grflow_contact.h"
#include "grflow_liggghts.h"

#include "atom.h"
#include "error.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "modify.h"
#include "pair_gran.h"
#include "update.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace LIGGGHTS {
namespace ContactModels {

  namespace GRFLOWProperties {
    // fix property/global NAME peratomtypepair N ... for each coefficient
    template <int K> MatrixProperty *create(PropertyRegistry &registry, const char *caller, bool)
    {
      return MODEL_PARAMS::createPerTypePairProperty(registry, LAMMPS_NS::GRFLOW::COEFF_NAMES[K],
                                                     caller);
    }
    static const MatrixPropertyCreator CREATORS[LAMMPS_NS::GRFLOW::NCOEFF] = {
        &create<0>, &create<1>, &create<2>, &create<3>, &create<4>, &create<5>,
        &create<6>, &create<7>, &create<8>, &create<9>, &create<10>};
  }    // namespace GRFLOWProperties

  template <> class NormalModel<NORMAL_GRFLOW> : public NormalModelBase {
   public:
    // the contact history: the kernel's springs, then the step of the
    // last evaluation that touched (grflow_liggghts.h)
    enum {
      STAMP = LAMMPS_NS::GRFLOW::LIGGGHTS_STAMP,
      NHISTORY = LAMMPS_NS::GRFLOW::LIGGGHTS_HISTORY
    };

    NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
        NormalModelBase(lmp, hsetup, c), rolling(true), torsion(true), limit_force(true),
        is_pair(false),
        history_offset(-1), ntypes(0)
    {
      for (int k = 0; k < LAMMPS_NS::GRFLOW::NCOEFF; k++) property[k] = NULL;
    }

    ~NormalModel()
    {
      // unpublish (a new pair style or a clear replaces this one)
      std::map<const LAMMPS *, LAMMPS_NS::GRFLOW::LiggghtsPairLaw> &laws =
          LAMMPS_NS::GRFLOW::liggghts_pair_laws();
      if (is_pair && laws.count(lmp) && laws[lmp].coeff == &coeff) laws.erase(lmp);
    }

    inline void registerSettings(Settings &settings)
    {
      settings.registerOnOff("rolling", rolling, true);
      settings.registerOnOff("torsion", torsion, true);
      // LIGGGHTS's name (model hooke, hertz) for the clipped normal force
      // f_n = max(k_n delta - c_n v_n, 0); off: the unclipped law of
      // granular/grflow's normal_force unclipped.  Default on (clipped),
      // unlike model hooke, as granular/grflow's default
      settings.registerOnOff("limitForce", limit_force, true);
    }

    inline void postSettings(IContactHistorySetup *hsetup, ContactModelBase *cmb)
    {
      // the kernel computes every mode: no other model may add forces
      static const char *const others[] = {"tangential", "rolling_friction", "cohesion"};
      for (const char *kind : others) {
        if (contact_match(hsetup, kind, "off")) continue;
        error->all(FLERR,
                   (std::string("model grflow computes sliding, rolling and torsion itself: ") +
                    kind + " must be off (leave out the " + kind + " keyword)")
                       .c_str());
      }
      is_pair = dynamic_cast<PairGran *>(hsetup) != NULL;
      if (!contact_match(hsetup, "surface", "default"))
        error->all(FLERR, "model grflow works with the default surface model (spheres) only");

      // sliding springs flip sign when i and j swap (newtonflag 1), the
      // rolling and torsion springs and the stamp do not (grflow_contact.h)
      static const char *const names[NHISTORY] = {"grflow_xt_x", "grflow_xt_y", "grflow_xt_z",
                                                  "grflow_xr_x", "grflow_xr_y", "grflow_xr_z",
                                                  "grflow_xo",   "grflow_step"};
      for (int k = 0; k < NHISTORY; k++) {
        const bool flips = k < STAMP && LAMMPS_NS::GRFLOW::HISTORY_SWAP_FACTOR[k] < 0.0;
        const int offset = hsetup->add_history_value(names[k], flips ? "1" : "0");
        if (k == 0) history_offset = offset;
      }
      cmb->add_history_offset("grflow", history_offset);
    }

    inline void connectToProperties(PropertyRegistry &registry)
    {
      using namespace LAMMPS_NS::GRFLOW;
      if (force->cg_active()) error->cg(FLERR, "model grflow");
      // kn and cn are required; a coefficient without its fix
      // property/global takes the ratio of the paper's Table 1
      const int max_type = registry.max_type();
      for (int k = 0; k < NCOEFF; k++) {
        property[k] = NULL;
        const bool given =
            modify->find_fix_property(COEFF_NAMES[k], "property/global", "peratomtypepair",
                                      max_type, max_type, "model grflow", false) != NULL;
        if (k > CN && !given) continue;
        registry.registerProperty(COEFF_NAMES[k], GRFLOWProperties::CREATORS[k]);
        registry.connect(COEFF_NAMES[k], property[k], "model grflow");
      }
      pack(max_type);
    }

    inline double stressStrainExponent() { return 1.0; }

    // the coefficients of every type pair, checked, packed for the kernel
    // (per pass: fix adapt may change a property between steps)
    inline void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) { pack(ntypes); }
    inline void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

    inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                  ForceData &j_forces)
    {
      using namespace LAMMPS_NS::GRFLOW;
      if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
      const bool update_history = sidata.computeflag && sidata.shearupdate;

      ContactGeometry g;
      if (sidata.is_wall) {
        // en points from the wall to the centre; deltan is the overlap
        plane_geometry(sidata.en, sidata.deltan, sidata.radi, false, g);
      } else {
        pair_geometry(sidata.delta, sidata.r, sidata.radi, sidata.radj, false, g);
      }
      const double vrel[3] = {sidata.v_i[0] - sidata.v_j[0], sidata.v_i[1] - sidata.v_j[1],
                              sidata.v_i[2] - sidata.v_j[2]};
      static const double no_spin[3] = {0.0, 0.0, 0.0};
      const double *omega_j = sidata.is_wall ? no_spin : sidata.omega_j;

      // the springs of this contact: zero if the pair did not touch on the
      // last step (LIGGGHTS keeps the history of a listed pair that parted)
      double *stored = &sidata.contact_history[history_offset];
      const double step = static_cast<double>(update->ntimestep);
      double hist[HIST_SIZE];
      current_springs(stored, step, sidata.computeflag && !sidata.shearupdate, hist);

      ContactForces out;
      contact_forces(coeff[sidata.itype * (ntypes + 1) + sidata.jtype], g, vrel, sidata.omega_i,
                     omega_j, update->dt, update_history, hist, out);

      if (update_history) {
        for (int k = 0; k < HIST_SIZE; k++) stored[k] = hist[k];
        stored[STAMP] = step;
      }
      sidata.Fn = out.fn;
      for (int d = 0; d < 3; d++) {
        i_forces.delta_F[d] += out.f[d];
        i_forces.delta_torque[d] += out.torque_i[d];
        j_forces.delta_F[d] -= out.f[d];
        j_forces.delta_torque[d] += out.torque_j[d];
      }
    }

    // not touching: nothing to do (the stamp drops the springs at the next touch)
    inline void surfacesClose(SurfacesCloseData &, ForceData &, ForceData &) {}

   private:
    bool rolling, torsion;
    bool limit_force;    // clipped normal force (limitForce on)
    bool is_pair;    // of pair_style gran (not of a wall)
    int history_offset;
    double **property[LAMMPS_NS::GRFLOW::NCOEFF];
    int ntypes;
    std::vector<LAMMPS_NS::GRFLOW::ContactCoeffs> coeff;    // (ntypes+1)^2, by itype, jtype

    // the pair style's or wall fix's choice of another kind of model
    bool contact_match(IContactHistorySetup *hsetup, const char *kind, const char *model)
    {
      if (PairGran *pg = dynamic_cast<PairGran *>(hsetup)) return pg->contact_match(kind, model);
      if (FixWallGran *fw = dynamic_cast<FixWallGran *>(hsetup))
        return fw->contact_match(kind, model);
      return true;
    }

    void pack(int max_type)
    {
      using namespace LAMMPS_NS::GRFLOW;
      if (!property[KN] || !property[CN]) return;    // before connectToProperties()
      ntypes = max_type;
      coeff.resize((ntypes + 1) * (ntypes + 1));
      for (int i = 1; i <= ntypes; i++)
        for (int j = 1; j <= ntypes; j++) {
          double value[NCOEFF];
          default_coeffs(property[KN][i][j], property[CN][i][j], value);
          for (int k = KT; k < NCOEFF; k++)
            if (property[k]) value[k] = property[k][i][j];
          if (!rolling) mode_off(KR, value);
          if (!torsion) mode_off(KO, value);
          const char *rule = "";
          const int bad = bad_coeff(value, &rule);
          if (bad < NCOEFF) {
            std::ostringstream msg;
            msg << "model grflow: " << COEFF_NAMES[bad] << " of types " << i << " " << j << " "
                << rule << ", got " << value[bad] << " (fix property/global " << COEFF_NAMES[bad]
                << ")";
            error->all(FLERR, msg.str().c_str());
          }
          ContactCoeffs &c = coeff[i * (ntypes + 1) + j];
          pack_coeffs(value, c);
          c.normal_law = limit_force ? NORMAL_CLIPPED : NORMAL_UNCLIPPED;
        }
      if (is_pair) {
        LiggghtsPairLaw law = {&coeff, ntypes, history_offset};
        liggghts_pair_laws()[lmp] = law;
      }
    }
  };

}    // namespace ContactModels
}    // namespace LIGGGHTS

#endif
#endif
