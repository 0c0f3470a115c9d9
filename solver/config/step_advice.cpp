#include "config/step_advice.hpp"

#include <sstream>

namespace slidewave {

std::optional<std::string> small_step_advice(const RunConfig& config) {
  const FrictionConfig& friction = config.friction;
  if (friction.f <= 0 || friction.regularization != Regularization::none) return std::nullopt;
  if (config.mesh.mass == MassKind::redistributed) return std::nullopt;  // what cures it
  const DerivedConstants d = config.derived();
  const double courant = d.c_s * d.dt / d.h;
  if (!(courant < kSmallCourantNumber)) return std::nullopt;
  std::ostringstream advice;
  advice.precision(3);
  advice << "advice: the time step is small for the mesh (c_s dt / h = " << courant << " < " << kSmallCourantNumber
         << "): with unregularized Coulomb friction, long runs at c_s dt / h <= 0.384 were measured to create energy "
            "once they slide (they are categorized non_physical); use time.dt_times_cs >= "
         << kSmallCourantNumber * d.h << " m at this mesh, mesh.mass = \"redistributed\" or "
         << "friction.regularization = \"prakash_clifton\" "
         << "(docs/physics-notes.md, section 8)";
  return advice.str();
}

}  // namespace slidewave
