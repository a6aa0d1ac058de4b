#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "mpm/core/tensor.hpp"

namespace mpm {

// Stress and internal variables of one material point. `stress` is the
// effective Cauchy stress sigma' (Tran et al., MPMICE, eq. 3: sigma = sigma' - p I),
// tension positive as in MPMICE; 3 x 3 and symmetric in 2D too.
struct MaterialState {
  Tensor stress = Tensor::Zero();
  double plastic_strain = 0.0;       // accumulated equivalent plastic shear strain [-]
  double damage = 0.0;               // cohesion degradation, 0 intact .. 1 fully degraded [-]
  std::array<double, 2> internal{};  // model-specific (documented by each model)
};

// What the kinematics of one step give a constitutive model.
struct Deformation {
  // Delta eps = sym(grad v) dt, in the frame the model works in: unrotated
  // (polar decomposition, MPMICE eqs. 11-13) or spatial (Jaumann rate).
  Tensor strain_increment = Tensor::Zero();
  // Deformation gradient at the end of the step (plane strain: F_zz = 1).
  Tensor deformation_gradient = Tensor::Identity();
  double dt = 0.0;
};

// How a hypoelastic model's stress is kept objective under rotation; chosen
// per material, applied by the solver around Material::update.
enum class ObjectiveRate {
  jaumann,         // Zheng et al., eq. 5
  polar_rotation,  // Tran et al., MPMICE, eqs. 11-14
};

// What a material needs to store and conduct heat (Tran et al., MPMICE,
// eq. 9). For a porous body both are the grains': the skeleton stores
// m_s c with its solid mass m_s and conducts with (1 - n) k (eq. 55).
struct ThermalProperties {
  double specific_heat = 0.0;  // c [J/(kg K)]
  double conductivity = 0.0;   // k [W/(m K)]
};

// The properties every model has, whatever its constitutive law.
struct CommonProperties {
  double density = 0.0;                      // [kg/m3]
  std::optional<ThermalProperties> thermal;  // none: the material takes no part in heat conduction
};

// A constitutive model with its parameters. Materials are immutable once
// built (by the registry, from a validated YAML mapping) and shared by all
// points of the bodies that use them; all per-point data is in MaterialState.
class Material {
 public:
  virtual ~Material() = default;

  // The registry name of the model ("mohr_coulomb").
  virtual std::string_view type() const = 0;

  // Solid grain density or bulk density as configured [kg/m3].
  double density() const { return common_.density; }
  const std::optional<ThermalProperties>& thermal() const { return common_.thermal; }
  // Moduli for the critical time step (Zheng et al., eq. 22) [Pa].
  virtual double bulk_modulus() const = 0;
  virtual double shear_modulus() const = 0;
  double p_wave_modulus() const { return bulk_modulus() + 4.0 / 3.0 * shear_modulus(); }

  // Hyperelastic models compute the stress from the deformation gradient
  // alone; the solver then skips the objective-rate rotation.
  virtual bool is_hyperelastic() const { return false; }
  ObjectiveRate objective_rate() const { return objective_rate_; }

  // Initial state of a point (e.g. internal variables at their start values).
  virtual void initialise(MaterialState& state) const { (void)state; }

  // Advances the state over one step.
  virtual void update(const Deformation& deformation, MaterialState& state) const = 0;

  // Yield function at a state: <= 0 admissible, > 0 outside the surface,
  // scaled as a stress [Pa]. Elastic models return -infinity.
  virtual double yield_function(const MaterialState& state) const {
    (void)state;
    return -std::numeric_limits<double>::infinity();
  }

  // Friction and dilation angle in use at a state [rad] (0 when the model has none);
  // used for K0 initialisation and outputs.
  virtual double friction_angle(const MaterialState& state) const {
    (void)state;
    return 0.0;
  }

 protected:
  Material(CommonProperties common, ObjectiveRate rate) : common_(common), objective_rate_(rate) {}

 private:
  CommonProperties common_;
  ObjectiveRate objective_rate_;
};

}  // namespace mpm
