#include "riser_sim/model.h"

#include <cmath>
#include <stdexcept>

#include "riser_sim/force_term.h"

namespace riser_sim {

Model::Model(double length, int segments, const LineProperties& props, const ModelOptions& options,
             double end_mass, double gravity)
    : n_(segments), length_(length), d_(length / segments), props_(props), options_(options),
      end_mass_(end_mass), gravity_(gravity) {
  if (segments < 1) throw std::invalid_argument("line.elements: must be >= 1");
  if (!(length > 0.0)) throw std::invalid_argument("line.length: must be > 0");
  if (!(props.mass_per_length > 0.0)) throw std::invalid_argument("line.mass_per_length: must be > 0");
  rfe_.resize(n_ + 1);
  double s = 0.0;
  for (int i = 0; i <= n_; ++i) {
    Rfe& r = rfe_[i];
    r.length = (i == 0 || i == n_) ? 0.5 * d_ : d_;  // half-length end elements (paper Fig. 1)
    r.length1 = 0.5 * r.length;
    r.length2 = r.length - r.length1;
    r.axial_stiffness = props.EA / r.length;  // paper eq. 3
    r.axial_damping = props.axial_damping / r.length;
    r.s_begin = s;
    s += r.length;
    const double mpl = props.mass_per_length + props.content_mass_per_length;
    const double m1 = mpl * r.length1, m2 = mpl * r.length2;
    if (props.axial_damping_ratio > 0.0)  // the element's halves, without the end mass: the line's own mode
      r.axial_damping += 2.0 * props.axial_damping_ratio * std::sqrt(r.axial_stiffness * m1 * m2 / (m1 + m2));
    // Thin-rod parts: centre of part (1) at l1/2; part (2) at l1 + Δ + l2/2 (paper eq. 16).
    r.part[0] = RigidPart{m1, m1 * r.length1 * r.length1 / 12.0, 0.5 * r.length1, 0.0};
    r.part[1] = RigidPart{m2, m2 * r.length2 * r.length2 / 12.0, r.length1 + 0.5 * r.length2, 1.0};
    r.num_parts = 2;
    if (i == n_ && end_mass > 0.0) {
      r.part[2] = RigidPart{end_mass, 0.0, r.length, 1.0};  // point mass m_s at the free end
      r.num_parts = 3;
    }
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& q = r.part[p];
      r.mass += q.mass;
      r.mass_k += q.mass * q.kappa;
      r.S0 += q.mass * q.s0;
      r.Sk0 += q.mass * q.kappa * q.s0;
      r.I0 += q.mass * q.s0 * q.s0 + q.inertia;
    }
  }
}

double Model::totalMass() const {
  return (props_.mass_per_length + props_.content_mass_per_length) * length_ + end_mass_ + point_mass_;
}

void Model::addPointMass(int i, double mass, double s0, double kappa) {
  if (i < 0 || i > n_ || !(mass >= 0.0) || !(s0 >= 0.0 && s0 <= rfe_[i].length) || (kappa != 0.0 && kappa != 1.0))
    throw std::invalid_argument("Model::addPointMass: rfe " + std::to_string(i) + ", mass " + std::to_string(mass) +
                                " kg, s0 " + std::to_string(s0) + " m, kappa " + std::to_string(kappa) + " is not on the line");
  Rfe& r = rfe_[i];
  int p = r.num_parts;
  for (int k = 2; k < r.num_parts; ++k)
    if (r.part[k].kappa == kappa) p = k;
  if (p == r.num_parts) {
    if (p == 4) throw std::logic_error("Model::addPointMass: no part left on rfe " + std::to_string(i));
    r.part[p] = RigidPart{0.0, 0.0, s0, kappa};
    ++r.num_parts;
  }
  // Merged: mass-weighted centre, parallel-axis inertia.
  RigidPart& q = r.part[p];
  const double m = q.mass + mass, c = m > 0.0 ? (q.mass * q.s0 + mass * s0) / m : s0;
  q.inertia += q.mass * (q.s0 - c) * (q.s0 - c) + mass * (s0 - c) * (s0 - c);
  q.mass = m;
  q.s0 = c;
  r.mass += mass;
  r.mass_k += mass * kappa;
  r.S0 += mass * s0;
  r.Sk0 += mass * kappa * s0;
  r.I0 += mass * s0 * s0;
  point_mass_ += mass;
}

void Model::addTerm(std::unique_ptr<ForceTerm> term) { terms_.push_back(std::move(term)); }

const ForceTerm* Model::findTerm(const std::string& name) const {
  for (const auto& t : terms_)
    if (t->name() == name) return t.get();
  return nullptr;
}

}  // namespace riser_sim
