#include "contact/friction_law.hpp"

#include <functional>
#include <map>
#include <stdexcept>

#include "contact/coulomb_friction.hpp"
#include "contact/prakash_clifton.hpp"

namespace slidewave {

namespace {

using FrictionLawFactory = std::function<std::unique_ptr<FrictionLaw>(const FrictionConfig&)>;

/// The registry: one line per law, keyed by `friction.regularization`.
const std::map<Regularization, FrictionLawFactory>& registry() {
  static const std::map<Regularization, FrictionLawFactory> laws{
      {Regularization::none, [](const FrictionConfig& c) { return std::make_unique<CoulombFriction>(c.f); }},
      {Regularization::prakash_clifton,
       [](const FrictionConfig& c) { return std::make_unique<PrakashClifton>(c.f, c.pc_length, c.pc_velocity); }},
  };
  return laws;
}

}  // namespace

std::unique_ptr<FrictionLaw> make_friction_law(const FrictionConfig& config) {
  const auto law = registry().find(config.regularization);
  if (law == registry().end())
    throw std::logic_error("friction.regularization: no friction law registered in contact/friction_law.cpp");
  return law->second(config);
}

}  // namespace slidewave
