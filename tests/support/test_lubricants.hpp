// Lubricants built in code for the film-solver tests, so a test states its oil in full.
#pragma once

#include <memory>

#include "tehl/lubricant/constant_conductivity.hpp"
#include "tehl/lubricant/constant_density.hpp"
#include "tehl/lubricant/constant_viscosity.hpp"
#include "tehl/lubricant/dowson_higginson_density.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/lubricant/roelands_viscosity.hpp"

namespace tehl::testing {

inline constexpr double kReferenceT0 = 313.15;  // [K]

// An isoviscous, incompressible oil (for the rigid and analytic limits).
inline Lubricant IsoviscousOil(double eta0_pa_s, double rho0 = 870.0) {
  return Lubricant("isoviscous", "test", kReferenceT0, 2000.0, 0.0,
                   std::make_unique<ConstantViscosity>(ConstantViscosity::Parameters{eta0_pa_s}),
                   std::make_unique<ConstantDensity>(ConstantDensity::Parameters{rho0}),
                   std::make_unique<ConstantConductivity>(ConstantConductivity::Parameters{0.13}));
}

// The reference oil of VALIDATION.md section 3: eta0 = 0.04 Pa s, Z = 0.68 (Roelands, so
// Houpert's alpha = 2.238e-8 1/Pa), Dowson-Higginson density.
inline Lubricant ReferenceOil(double eta0_pa_s = 0.04, double z = 0.68) {
  RoelandsViscosity::Parameters v;
  v.viscosity_pa_s = eta0_pa_s;
  v.reference_temperature_k = kReferenceT0;
  v.pressure_index = z;
  v.temperature_index = 1.1;
  DowsonHigginsonDensity::Parameters d;
  d.density_kg_m3 = 870.0;
  d.reference_temperature_k = kReferenceT0;
  d.expansivity_per_k = 0.0;
  return Lubricant("reference_z068", "VALIDATION.md section 3", kReferenceT0, 2000.0, 0.0,
                   std::make_unique<RoelandsViscosity>(v),
                   std::make_unique<DowsonHigginsonDensity>(d),
                   std::make_unique<ConstantConductivity>(ConstantConductivity::Parameters{0.13}));
}

}  // namespace tehl::testing
