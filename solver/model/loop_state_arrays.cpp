#include "model/loop_state_arrays.hpp"

#include <stdexcept>

namespace slidewave {
namespace {

/// The vectors of the state by name (the same list writes and reads them).
template <typename State, typename F>
void for_each_vector(State& loop, F&& visit) {
  visit("u", loop.dynamics.u);
  visit("v", loop.dynamics.v);
  visit("acc", loop.dynamics.acc);
  visit("Ku", loop.dynamics.Ku);
  visit("Mu_f", loop.dynamics.Mu_f);
  visit("Mv_f", loop.dynamics.Mv_f);
  visit("Ma_f", loop.dynamics.Ma_f);
  visit("r", loop.dynamics.r);
  visit("F_top", loop.energy.F_top);
  visit("u_contact_start", loop.recording.u_contact_start);
  if (loop.energy.hht.on()) {  // output.energy_decomposition = hht
    visit("hht_v_f", loop.energy.hht.v_f);
    visit("hht_acc_f", loop.energy.hht.acc_f);
    visit("hht_Ma_f", loop.energy.hht.Ma_f);
    visit("hht_Ku_f", loop.energy.hht.Ku_f);
    visit("hht_shift_f", loop.energy.hht.shift_f);
  }
  if (loop.substrate.u.size() > 0) {  // the deformable substrate (model/substrate.hpp)
    visit("substrate_u", loop.substrate.u);
    visit("substrate_v", loop.substrate.v);
    visit("substrate_acc", loop.substrate.acc);
    visit("substrate_Ku", loop.substrate.Ku);
    visit("substrate_Mu_f", loop.substrate.Mu_f);
    visit("substrate_Mv_f", loop.substrate.Mv_f);
    visit("substrate_Ma_f", loop.substrate.Ma_f);
    visit("substrate_r", loop.substrate.r);
    visit("substrate_F_top", loop.substrate_energy.F_top);
    if (loop.substrate_energy.hht.on()) {
      visit("substrate_hht_v_f", loop.substrate_energy.hht.v_f);
      visit("substrate_hht_acc_f", loop.substrate_energy.hht.acc_f);
      visit("substrate_hht_Ma_f", loop.substrate_energy.hht.Ma_f);
      visit("substrate_hht_Ku_f", loop.substrate_energy.hht.Ku_f);
      visit("substrate_hht_shift_f", loop.substrate_energy.hht.shift_f);
    }
  }
}

/// The array `name` of one kind (a.reals or a.integers), which must hold `size` values for this model.
template <class Arrays>
const typename Arrays::mapped_type& find_array(const Arrays& arrays, const std::string& name, std::size_t size) {
  const auto found = arrays.find(name);
  if (found == arrays.end()) throw std::runtime_error("checkpoint: no array " + name);
  if (found->second.size() != size)
    throw std::runtime_error("checkpoint: " + name + " has " + std::to_string(found->second.size()) +
                             " values, this model " + std::to_string(size));
  return found->second;
}

const char* const kEndReasons[] = {"t_end", "stop_after_opening"};

}  // namespace

StateArrays to_arrays(const LoopState& loop) {
  StateArrays a;
  for_each_vector(
      loop, [&](const char* name, const Eigen::VectorXd& v) { a.reals[name].assign(v.data(), v.data() + v.size()); });
  a.reals["friction"] = loop.friction.per_node;
  a.reals["scalars"] = {loop.t_end,
                        loop.energy.energy_start,
                        loop.energy.work_external,
                        loop.energy.dissipation_friction,
                        loop.energy.work_contact_normal,
                        loop.recording.t_first_opening};
  if (loop.energy.hht.on()) a.reals["hht_terms"] = {loop.energy.hht.gamma, loop.energy.hht.beta, loop.energy.hht.shift};
  if (loop.substrate.u.size() > 0) {
    const EnergySums& e = loop.substrate_energy;
    a.reals["substrate_sums"] = {
        e.energy_start, e.work_external, e.dissipation_friction, e.work_contact_normal, e.hht.gamma,
        e.hht.beta,     e.hht.shift};
  }
  auto& contact = a.integers["contact"];
  for (const ContactState s : loop.contact) contact.push_back(static_cast<std::int64_t>(s));
  std::int64_t end_reason = -1;
  for (std::int64_t k = 0; k < 2; ++k)
    if (loop.end_reason == kEndReasons[k]) end_reason = k;
  if (end_reason < 0) throw std::runtime_error("checkpoint: unknown end_reason " + loop.end_reason);
  a.integers["counters"] = {loop.step, static_cast<std::int64_t>(loop.recording.next_snapshot), end_reason};
  return a;
}

void restore_from_arrays(const StateArrays& a, LoopState& loop) {
  for_each_vector(loop, [&](const char* name, Eigen::VectorXd& v) {
    const auto& values = find_array(a.reals, name, static_cast<std::size_t>(v.size()));
    std::copy(values.begin(), values.end(), v.data());
  });
  loop.friction.per_node = find_array(a.reals, "friction", loop.friction.per_node.size());
  const auto& scalars = find_array(a.reals, "scalars", 6);
  loop.t_end = scalars[0];
  loop.energy.energy_start = scalars[1];
  loop.energy.work_external = scalars[2];
  loop.energy.dissipation_friction = scalars[3];
  loop.energy.work_contact_normal = scalars[4];
  loop.recording.t_first_opening = scalars[5];
  if (loop.energy.hht.on()) {
    const auto& terms = find_array(a.reals, "hht_terms", 3);
    loop.energy.hht.gamma = terms[0];
    loop.energy.hht.beta = terms[1];
    loop.energy.hht.shift = terms[2];
  }
  if (loop.substrate.u.size() > 0) {
    const auto& sums = find_array(a.reals, "substrate_sums", 7);
    EnergySums& e = loop.substrate_energy;
    e.energy_start = sums[0];
    e.work_external = sums[1];
    e.dissipation_friction = sums[2];
    e.work_contact_normal = sums[3];
    e.hht.gamma = sums[4];
    e.hht.beta = sums[5];
    e.hht.shift = sums[6];
  }
  const auto& contact = find_array(a.integers, "contact", loop.contact.size());
  for (std::size_t k = 0; k < contact.size(); ++k) loop.contact[k] = static_cast<ContactState>(contact[k]);
  const auto& counters = find_array(a.integers, "counters", 3);
  if (counters[2] < 0 || counters[2] > 1) throw std::runtime_error("checkpoint: bad end_reason code");
  loop.step = counters[0];
  loop.recording.next_snapshot = static_cast<std::size_t>(counters[1]);
  loop.end_reason = kEndReasons[counters[2]];
}

}  // namespace slidewave
