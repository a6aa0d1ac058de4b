#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cosim/error.hpp"
#include "exchange/beetstra.hpp"
#include "exchange/constant_drag.hpp"
#include "exchange/drag_law_registry.hpp"
#include "exchange/forchheimer.hpp"
#include "exchange/hydraulic_conductivity.hpp"
#include "exchange/kozeny_carman.hpp"

namespace cosim::exchange {
namespace {

constexpr double kWaterViscosity = 1.0e-3;  // Pa s
constexpr double kWaterDensity = 1000.0;    // kg m^-3
constexpr double kGravity = 9.81;           // m s^-2

std::unique_ptr<DragLaw> law_from(const std::string& yaml) {
  return make_drag_law(YAML::Load(yaml), "momentum_exchange.drag", "job.yaml");
}

DragInput cell(double phi_s, double relative_speed = 0.0) {
  DragInput input;
  input.solid_fraction = phi_s;
  input.fluid_density = kWaterDensity;
  input.relative_speed = relative_speed;
  return input;
}

double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

TEST(KozenyCarman, GrainSizeFormMatchesEq29ByHand) {
  // phi_s = 0.4, D_p = 1 mm, mu = 1e-3: 180 * 0.16 * 1e-3 / (1e-6 * 0.6) = 48000
  const auto law = law_from("{law: kozeny_carman, grain_size: 1.0e-3, fluid_viscosity: 1.0e-3}");
  const double k = law->coefficient(cell(0.4));
  std::printf("Kozeny-Carman eq. 29: K = %.17g (hand 48000), rel. error %.3g\n", k,
              relative_error(k, 48000.0));
  EXPECT_LT(relative_error(k, 48000.0), 1e-14);
  EXPECT_EQ(law->cell_input(), CellInput::none);
}

TEST(KozenyCarman, PermeabilityFormMatchesEq30ByHand) {
  // n = 0.6, kappa = 1e-10, mu = 1e-3: 0.36 * 1e-3 / 1e-10 = 3.6e6
  const auto law = law_from("{law: kozeny_carman, permeability: 1.0e-10, fluid_viscosity: 1.0e-3}");
  const double k = law->coefficient(cell(0.4));
  std::printf("Kozeny-Carman eq. 30: K = %.17g (hand 3.6e6), rel. error %.3g\n", k,
              relative_error(k, 3.6e6));
  EXPECT_LT(relative_error(k, 3.6e6), 1e-14);
}

TEST(KozenyCarman, Eq29AndEq30AgreeThroughConductivityEq32AndEq31) {
  for (const double phi_s : {0.1, 0.35, 0.6}) {
    for (const double d : {1e-4, 2e-3}) {
      const double conductivity =
          kozeny_carman_conductivity(d, phi_s, kWaterViscosity, kWaterDensity, kGravity);
      const double kappa =
          permeability_from_conductivity(conductivity, kWaterViscosity, kWaterDensity, kGravity);
      const KozenyCarman from_grain(kWaterViscosity, KozenyCarman::Basis::grain_size, d);
      const KozenyCarman from_kappa(kWaterViscosity, KozenyCarman::Basis::permeability, kappa);
      const double error =
          relative_error(from_kappa.coefficient(cell(phi_s)), from_grain.coefficient(cell(phi_s)));
      std::printf("phi_s %.2f D %.1e: K_h %.4e m/s, kappa %.4e m^2, eq29 vs eq30 rel. diff %.3g\n",
                  phi_s, d, conductivity, kappa, error);
      EXPECT_LT(error, 1e-14);
      EXPECT_LT(relative_error(
                    conductivity_from_permeability(kappa, kWaterViscosity, kWaterDensity, kGravity),
                    conductivity),
                1e-15);
    }
  }
}

TEST(KozenyCarman, ReadsThePerCellFieldWhenConfiguredAsField) {
  const auto law = law_from("{law: kozeny_carman, permeability: field, fluid_viscosity: 1.0e-3}");
  EXPECT_EQ(law->cell_input(), CellInput::permeability);
  DragInput input = cell(0.4);
  input.permeability = 2.0e-10;
  EXPECT_LT(relative_error(law->coefficient(input), 1.8e6), 1e-14);
  input.permeability = 0.0;
  EXPECT_THROW(law->coefficient(input), NumericalError);
}

TEST(Forchheimer, MatchesPanEq3And4ByHand) {
  // n = 0.4, D50 = 1 mm: k = 1e-6 * 0.064 / (150 * 0.36) = 1.185185...e-9 m^2
  // K = 0.16 * 1e-3 / k + 1.75 * 1000 * sqrt(0.4) * 0.02 / sqrt(150 k)
  const double k = 1e-6 * 0.064 / (150.0 * 0.36);
  EXPECT_LT(relative_error(kozeny_carman_permeability(1e-3, 0.4), k), 1e-15);
  const double hand = 0.16 * 1e-3 / k + 1.75 * 1000.0 * std::sqrt(0.4) * 0.02 / std::sqrt(150 * k);
  const auto law = law_from("{law: forchheimer, grain_size: 1.0e-3, fluid_viscosity: 1.0e-3}");
  const double value = law->coefficient(cell(0.6, 0.02));
  std::printf("Forchheimer: K = %.17g (hand %.17g), rel. error %.3g\n", value, hand,
              relative_error(value, hand));
  EXPECT_LT(relative_error(value, hand), 1e-14);
  // Linear part alone at zero relative speed is eq. 30 with k from eq. 4.
  EXPECT_LT(relative_error(law->coefficient(cell(0.6, 0.0)), 0.16 * 1e-3 / k), 1e-14);
}

TEST(Beetstra, LowReynoldsLimitIsEq28) {
  // F(0.4, 0) = 10 * 0.4 / 0.36 + 0.36 * (1 + 1.5 sqrt(0.4))
  const double hand = 4.0 / 0.36 + 0.36 * (1.0 + 1.5 * std::sqrt(0.4));
  for (const double phi_s : {0.1, 0.4, 0.6}) {
    const double limit = beetstra_f(phi_s, 0.0);
    const double tiny = beetstra_f(phi_s, 1e-300);
    std::printf("Beetstra F(%.1f, 0) = %.17g, F(%.1f, 1e-300) - F0 = %.3g\n", phi_s, limit, phi_s,
                tiny - beetstra_f0(phi_s));
    EXPECT_TRUE(std::isfinite(limit));
    EXPECT_EQ(limit, beetstra_f0(phi_s));
    EXPECT_EQ(tiny, beetstra_f0(phi_s));
  }
  EXPECT_LT(relative_error(beetstra_f0(0.4), hand), 1e-15);
}

TEST(Beetstra, MatchesTranEq25To27ByHand) {
  // phi_s = 0.4, D = 1 mm, mu = 1e-3, rho_f = 1000, |w| = 0.05:
  // Re = 0.6 * 1000 * 1e-3 * 0.05 / 1e-3 = 30 (eq. 26); eq. 27 in its printed form.
  const double phi = 0.4;
  const double re = 30.0;
  const double f0 =
      10 * phi / ((1 - phi) * (1 - phi)) + (1 - phi) * (1 - phi) * (1 + 1.5 * std::sqrt(phi));
  const double f = f0 + 0.413 * re / (24 * (1 - phi) * (1 - phi)) *
                            ((1 / (1 - phi) + 3 * phi * (1 - phi) + 8.4 * std::pow(re, -0.343)) /
                             (1 + std::pow(10.0, 3 * phi) * std::pow(re, -(1 + 4 * phi) / 2)));
  const double hand = 18 * phi * (1 - phi) * 1e-3 / 1e-6 * f;
  const auto law = law_from("{law: beetstra, grain_size: 1.0e-3, fluid_viscosity: 1.0e-3}");
  const double value = law->coefficient(cell(phi, 0.05));
  std::printf("Beetstra: F(0.4, 30) = %.6f, K = %.17g (hand %.17g), rel. error %.3g\n", f, value,
              hand, relative_error(value, hand));
  EXPECT_LT(relative_error(value, hand), 1e-13);
  // With F = 10 phi_s / (1 - phi_s)^2 the law is Kozeny-Carman eq. 29.
  EXPECT_GT(value, 180 * phi * phi * 1e-3 / (1e-6 * (1 - phi)));
}

TEST(ConstantDrag, ReturnsTheConfiguredCoefficient) {
  const auto law = law_from("{law: constant, coefficient: 1.0e15}");
  EXPECT_EQ(law->coefficient(cell(0.3, 2.0)), 1.0e15);
  EXPECT_EQ(law->name(), "constant");
}

TEST(DragLawFactory, ListsTheBuiltInLaws) {
  const auto names = DragLawRegistry::instance().types();
  for (const char* name : {"beetstra", "constant", "forchheimer", "kozeny_carman"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
}

TEST(DragLawFactory, AcceptsARegisteredLaw) {
  config::Schema schema = config::Schema::object();
  schema.required("law", config::Schema::one_of({"scaled_test_law"}), "")
      .required("half", config::Schema::number().positive(), "");
  DragLawRegistry::instance().add("scaled_test_law", schema, [](const config::Node& node) {
    return std::make_unique<ConstantDrag>(2.0 * node["half"].as<double>());
  });
  EXPECT_EQ(law_from("{law: scaled_test_law, half: 3.0}")->coefficient(cell(0.5)), 6.0);
}

void expect_input_error(const std::string& yaml, const std::string& key, const std::string& text) {
  try {
    law_from(yaml);
    ADD_FAILURE() << "no InputError for " << yaml;
  } catch (const InputError& error) {
    std::printf("%s\n  -> %s\n", yaml.c_str(), error.what());
    EXPECT_EQ(error.key_path(), "momentum_exchange.drag." + key);
    EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("job.yaml:1:"), std::string::npos) << error.what();
  }
}

TEST(DragLawFactory, MissingOrScalarNodeThrowsInputError) {
  const YAML::Node job = YAML::Load("momentum_exchange: {drag: kozeny_carman}");
  EXPECT_THROW(make_drag_law(job["momentum_exchange"]["drag"], "momentum_exchange.drag"),
               InputError);
  EXPECT_THROW(make_drag_law(job["momentum_exchange"]["drag_law"], "momentum_exchange.drag_law"),
               InputError);
}

TEST(DragLawFactory, BadParametersThrowInputErrorNamingTheKey) {
  expect_input_error("{law: darcy_weisbach}", "law", "unknown drag law 'darcy_weisbach'");
  expect_input_error("{grain_size: 1.0e-3}", "law", "missing");
  expect_input_error("{law: kozeny_carman, grain_size: 1.0e-3}", "fluid_viscosity", "missing");
  expect_input_error("{law: kozeny_carman, grain_size: -1.0e-3, fluid_viscosity: 1.0e-3}",
                     "grain_size", "> 0");
  expect_input_error("{law: kozeny_carman, grain_size: fine, fluid_viscosity: 1.0e-3}",
                     "grain_size", "expected number > 0 [m], or one of 'field'");
  expect_input_error("{law: kozeny_carman, fluid_viscosity: 1.0e-3}", "grain_size", "exactly one");
  expect_input_error(
      "{law: forchheimer, grain_size: 1.0e-3, permeability: 1.0e-9, fluid_viscosity: 1.0e-3}",
      "permeability", "exactly one");
  expect_input_error("{law: beetstra, grain_size: 1.0e-3, fluid_viscosity: 1.0e-3, viscosity: 2}",
                     "viscosity", "unknown key");
  expect_input_error("{law: constant, coefficient: .nan}", "coefficient", "finite");
  expect_input_error("{law: constant}", "coefficient", "missing");
}

}  // namespace
}  // namespace cosim::exchange
