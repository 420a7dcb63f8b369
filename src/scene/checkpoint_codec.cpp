// Encoding of contact conditions and cycle rows in checkpoints (checkpoint_codec.hpp).
#include "scene/checkpoint_codec.hpp"

namespace tehl::internal::checkpoint_codec {

void PutConditions(Out& o, const ContactConditions& c) {
  for (double v : {c.reduced_radius_m, c.u1_m_s, c.u2_m_s, c.load_n_per_m, c.temperature_k}) o.F(v);
}
ContactConditions GetConditions(In& in) {
  ContactConditions c;
  c.reduced_radius_m = in.F();
  c.u1_m_s = in.F();
  c.u2_m_s = in.F();
  c.load_n_per_m = in.F();
  c.temperature_k = in.F();
  return c;
}

void PutStep(Out& o, const MeshCycleStep& k) {
  for (double v : {k.s_m,
                   k.time_s,
                   k.reduced_radius_m,
                   k.u1_m_s,
                   k.u2_m_s,
                   k.um_m_s,
                   k.srr,
                   k.load_n_per_m,
                   k.static_load_n_per_m,
                   k.h_min_m,
                   k.h_c_m,
                   k.p_max_pa,
                   k.t_max_k,
                   k.t_mid_max_k,
                   k.t1_max_k,
                   k.t2_max_k,
                   k.friction_coefficient,
                   k.c_rt,
                   k.c_ut,
                   k.c_wt})
    o.F(v);
  o.I(k.pairs_in_contact);
  o.S(k.zone);
  const LineContactSolver::Summary& s = k.summary;
  o.I(static_cast<int>(s.termination));
  o.S(s.message);
  for (int v : {s.iterations, s.total_iterations, s.continuation_stages, s.krylov_iterations,
                s.substeps, s.coupling_iterations})
    o.I(v);
  for (double v : {s.residual, s.load_error, s.wall_time_s, s.temperature_change_k,
                   s.energy_balance_error, s.time_error})
    o.F(v);
  o.S(s.linear_solver);
  o.S(k.restart_reason);
  o.I(s.outlet_cut ? 1 : 0);
}

MeshCycleStep GetStep(In& in) {
  MeshCycleStep k;
  for (double* v : {&k.s_m,
                    &k.time_s,
                    &k.reduced_radius_m,
                    &k.u1_m_s,
                    &k.u2_m_s,
                    &k.um_m_s,
                    &k.srr,
                    &k.load_n_per_m,
                    &k.static_load_n_per_m,
                    &k.h_min_m,
                    &k.h_c_m,
                    &k.p_max_pa,
                    &k.t_max_k,
                    &k.t_mid_max_k,
                    &k.t1_max_k,
                    &k.t2_max_k,
                    &k.friction_coefficient,
                    &k.c_rt,
                    &k.c_ut,
                    &k.c_wt})
    *v = in.F();
  k.pairs_in_contact = static_cast<int>(in.I());
  k.zone = in.S();
  LineContactSolver::Summary& s = k.summary;
  s.termination = static_cast<LineContactSolver::Termination>(in.I());
  s.message = in.S();
  for (int* v : {&s.iterations, &s.total_iterations, &s.continuation_stages, &s.krylov_iterations,
                 &s.substeps, &s.coupling_iterations})
    *v = static_cast<int>(in.I());
  for (double* v : {&s.residual, &s.load_error, &s.wall_time_s, &s.temperature_change_k,
                    &s.energy_balance_error, &s.time_error})
    *v = in.F();
  s.linear_solver = in.S();
  k.restart_reason = in.S();
  s.outlet_cut = in.I() != 0;
  return k;
}

}  // namespace tehl::internal::checkpoint_codec
