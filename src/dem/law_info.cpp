// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/law_info.hpp"

namespace corlab::dem {

using restitution::Status;

const std::vector<LawInfo>& law_catalog() {
  static const std::vector<LawInfo> catalog = {
      {"hertz",
       "Hertz H. (1882), J. reine angew. Math. 92:156-171; Johnson (1985) Contact Mechanics eq. "
       "4.23",
       "F = 4/3 E* sqrt(R*) delta^1.5", Status::kVerifiedSecondSource,
       "textbook; checked against corlab's FE elastic impact "
       "(tests/verification/hertz_elastic_test)"},
      {"hunt_crossley", "Hunt K.H., Crossley F.R.E. (1975), J. Appl. Mech. 42:440-445",
       "F = K delta^1.5 (1 + chi delta_dot/v_in), chi = 3(1 - e)/2", Status::kVerifiedSecondSource,
       "formula confirmed in two secondary sources (issue 11 text; a public contact-model "
       "verification table)"},
      {"lankarani_nikravesh", "Lankarani H.M., Nikravesh P.E. (1990), J. Mech. Des. 112:369-376",
       "chi = 3(1 - e^2)/4", Status::kVerifiedSecondSource,
       "confirmed in two secondary sources (as hunt_crossley)"},
      {"flores",
       "Flores P., Machado M., Silva M.T., Martins J.M. (2011), Multibody Syst. Dyn. 25:357-375",
       "chi = 8(1 - e)/(5 e)", Status::kVerifiedSecondSource,
       "confirmed in two secondary sources (as hunt_crossley)"},
      {"gonthier",
       "Gonthier Y., McPhee J., Lange C., Piedboeuf J.-C. (2004), Multibody Syst. Dyn. 11:209-233",
       "chi = (1 - e^2)/e", Status::kVerifiedSecondSource,
       "confirmed in two secondary sources; equals carvalho_martins at e = 1/3 as the Exudyn docs "
       "state"},
      {"hu_guo", "Hu S., Guo X. (2015), Mech. Mach. Theory 85:14-31", "chi = 3(1 - e)/(2 e)",
       Status::kUnverified,
       "one source (issue 11 text); consistent with its stated delivered e = 0.271 at e = 0.3 "
       "(tests/unit/dem/hysteresis_chi_test). A second, independent implementation (the "
       "DyS multibody code, contact_model.py, 2015-16) uses 3(1 - e)/(4 e), half of it, which "
       "would deliver 0.446 at e = 0.3: the two sources disagree, the paper itself not read"},
      {"carvalho_martins", "Carvalho A.S., Martins J.M. (2019), Mech. Mach. Theory 139:174-194",
       "chi = 3(1 - e)(11 - e)/(2(1 + 9 e))", Status::kUnverified,
       "one secondary source (Exudyn documentation, ObjectConnectorRollingDiscPenalty/contact); "
       "the paper itself not read"},
      {"exact_hysteresis",
       "this work (integration of the contact ODE; cf. Carvalho & Martins 2019)",
       "chi (1 + e) = ln[(1 + chi)/(1 - e chi)], e = (1 + W0(-(1+chi) exp(-(1+chi))))/chi",
       Status::kVerifiedSecondSource,
       "derived in closed form and checked against ODE integration to 1e-8"},
      {"tsuji",
       "Tsuji Y., Tanaka T., Ishida T. (1992), Powder Technol. 71:239-250; LAMMPS pair granular",
       "F = K delta^1.5 + alpha sqrt(m* K) delta^0.25 delta_dot; exact alpha(e) by ODE",
       Status::kVerifiedSecondSource,
       "form read in LAMMPS source (pair_granular.cpp); alpha(e) by ODE"},
      {"viscoelastic_hertz",
       "Kuwabara G., Kono K. (1987), Jpn. J. Appl. Phys. 26:1230; "
       "Schwager T., Poeschel T. (2008), Phys. Rev. E 78:051304",
       "F = K delta^1.5 + c delta^0.5 delta_dot (LAMMPS damping viscoelastic: c = eta m* sqrt(R*))",
       Status::kVerifiedSecondSource, "form read in LAMMPS source; e(v) by ODE"},
      {"schwager_poeschel",
       "Ramirez R., Poeschel T., Brilliantov N.V., Schwager T. (1999), Phys. Rev. E 60:4465; "
       "Schwager T., Poeschel T. (2008), Phys. Rev. E 78:051304; Pade: Mueller P., Poeschel T. "
       "(2011), arXiv:1102.5247",
       "e(v) of viscoelastic_hertz: x = beta^0.5 v^0.1, beta = c K^-0.6 m*^-0.4; series "
       "e = 1 - 1.153449 x^2 + 0.798267 x^4; Pade e = (1 + 0.501086 x)/(1 + 0.501086 x + "
       "1.15345 x^2 + 0.577977 x^3 + 0.532178 x^4)",
       Status::kVerifiedSecondSource,
       "papers' text not read: C1, C2 re-derived in closed form; Pade numbers from one public "
       "secondary source; both checked against the contact ODE with force-free separation "
       "(series 2.5e-4 for x <= 0.3, Pade 5e-4 for x <= 0.5; "
       "tests/verification/schwager_poeschel_test)"},
      {"linear_spring_dashpot", "Cundall P.A., Strack O.D.L. (1979), Geotechnique 29:47-65",
       "F = k delta + c delta_dot; e = exp(-pi zeta/sqrt(1 - zeta^2)), zeta = c/(2 sqrt(m* k))",
       Status::kVerifiedSecondSource, "closed form checked against ODE integration"},
      {"thornton_ning",
       "Thornton C. (1997), J. Appl. Mech. 64:383-386 (loading/unloading; "
       "Thornton C., Ning Z. (1998), Powder Technol. 99:154-162 without adhesion)",
       "Hertz to p_y, then F = F_y + pi p_y R (delta - delta_y); Hertz unloading with R_p",
       Status::kVerifiedSecondSource,
       "e(v) by ODE equals corlab's thornton1997 closed form "
       "(tests/unit/dem/contact_ode_test)"},
  };
  return catalog;
}

}  // namespace corlab::dem
