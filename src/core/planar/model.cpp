#include "riser_sim/planar/model.h"

#include <cmath>
#include <stdexcept>

#include "riser_sim/planar/force_term.h"

namespace riser_sim {

Model::Model(double length, int segments, const LineProperties& props, const ModelOptions& options, double end_mass,
             double gravity)
    : Model(std::vector<LineSection>{LineSection{length, segments, props, SectionHydro(), BuoyancyModules()}}, {},
            options, end_mass, gravity) {}

Model::Model(const std::vector<LineSection>& sections, const std::vector<BendStiffener>& stiffeners,
             const ModelOptions& options, double end_mass, double gravity)
    : n_(0), length_(0.0), d_(0.0), sections_(sections), options_(options), end_mass_(end_mass), gravity_(gravity) {
  if (sections.empty()) throw std::invalid_argument("line.sections: at least one section");
  for (const LineSection& sec : sections) {
    if (sec.elements < 1) throw std::invalid_argument("line.elements: must be >= 1");
    if (!(sec.length > 0.0)) throw std::invalid_argument("line.length: must be > 0");
    if (!(sec.props.mass_per_length > 0.0)) throw std::invalid_argument("line.mass_per_length: must be > 0");
    n_ += sec.elements;
    length_ += sec.length;
  }
  uniform_ = sections.size() == 1 && stiffeners.empty();
  d_ = uniform_ ? sections[0].length / sections[0].elements : length_ / n_;
  const ResolvedLine line = resolveLine(sections, stiffeners);
  segment_ = line.segment;
  rfe_.resize(n_ + 1);
  double s = 0.0;
  for (int i = 0; i <= n_; ++i) {
    Rfe& r = rfe_[i];
    // Segment of part (1) and of part (2): rfe 0 and rfe n lie in one segment (half-length end elements,
    // paper Fig. 1), rfe i in segments i-1 and i, its spring at their boundary.
    const int j1 = i == 0 ? 0 : i - 1, j2 = i == n_ ? n_ - 1 : i;
    r.section[0] = line.section[j1];
    r.section[1] = line.section[j2];
    const LineProperties& p1 = sections_[r.section[0]].props;
    const LineProperties& p2 = sections_[r.section[1]].props;
    if (i == 0 || i == n_) {
      r.length = 0.5 * segment_[j1];
      r.length1 = 0.5 * r.length;
    } else {
      r.length = 0.5 * (segment_[j1] + segment_[j2]);
      r.length1 = 0.5 * segment_[j1];
    }
    r.length2 = r.length - r.length1;
    const bool same = r.section[0] == r.section[1];
    if (same) {
      r.axial_stiffness = p1.EA / r.length;  // paper eq. 3
      r.axial_damping = p1.axial_damping / r.length;
    } else {
      // The two halves in series: 1/k = l1/EA_1 + l2/EA_2; Kelvin-Voigt dampers in series at rates below
      // EA/c_EA: c = k² Σ l_p c_p / EA_p² (c_EA / l_i for equal halves).
      const double f1 = r.length1 / p1.EA, f2 = r.length2 / p2.EA;
      r.axial_stiffness = p1.EA > 0.0 && p2.EA > 0.0 ? 1.0 / (f1 + f2) : 0.0;
      const double k = r.axial_stiffness;
      r.axial_damping = k > 0.0 ? k * k * (f1 * p1.axial_damping / p1.EA + f2 * p2.axial_damping / p2.EA) : 0.0;
    }
    r.s_begin = s;
    s += r.length;
    const double m1 = (p1.mass_per_length + p1.content_mass_per_length) * r.length1;
    const double m2 = (p2.mass_per_length + p2.content_mass_per_length) * r.length2;
    const double zeta = same ? p1.axial_damping_ratio
                             : (r.length1 * p1.axial_damping_ratio + r.length2 * p2.axial_damping_ratio) / r.length;
    if (zeta > 0.0)  // the element's halves, without the end mass: the line's own mode
      r.axial_damping += 2.0 * zeta * std::sqrt(r.axial_stiffness * m1 * m2 / (m1 + m2));
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
  // Bending spring i (between rfes i-1 and i) at the middle of segment i-1: the rotation between the rfes is
  // the curvature integrated over that segment, Δφ = ∫ M/EI ds = M ∫ ds/EI with M constant over it.
  bend_k_.assign(n_ + 1, 0.0);
  bend_c_.assign(n_ + 1, 0.0);
  for (int i = 1; i <= n_ && options_.bending; ++i) {
    const int j = i - 1;
    const LineProperties& p = sections_[line.section[j]].props;
    bend_k_[i] =
        line.stiffened[j] ? (std::isfinite(line.compliance[j]) ? 1.0 / line.compliance[j] : 0.0) : p.EI / segment_[j];
    bend_c_[i] = p.bending_damping / segment_[j];
    has_bending_ = has_bending_ || bend_k_[i] > 0.0 || bend_c_[i] > 0.0;
  }
}

double Model::totalMass() const {
  if (uniform_) {
    const LineProperties& p = sections_[0].props;
    return (p.mass_per_length + p.content_mass_per_length) * length_ + end_mass_ + point_mass_;
  }
  double m = 0.0;
  for (const Rfe& r : rfe_) m += r.mass;  // includes the end mass (a part of rfe n)
  return m;
}

void Model::addPointMass(int i, double mass, double s0, double kappa) {
  if (i < 0 || i > n_ || !(mass >= 0.0) || !(s0 >= 0.0 && s0 <= rfe_[i].length) || (kappa != 0.0 && kappa != 1.0))
    throw std::invalid_argument("Model::addPointMass: rfe " + std::to_string(i) + ", mass " + std::to_string(mass) +
                                " kg, s0 " + std::to_string(s0) + " m, kappa " + std::to_string(kappa) +
                                " is not on the line");
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
