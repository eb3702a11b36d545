#include "riser_sim/line/line_properties.h"

#include <cmath>

namespace riser_sim {

LineProperties LineProperties::fromGeometry(double outer_diameter, double inner_diameter, double youngs_modulus,
                                            double density) {
  LineProperties p;
  p.outer_diameter = outer_diameter;
  p.inner_diameter = inner_diameter;
  const double area = p.wallArea();
  const double second_moment = M_PI / 64.0 * (std::pow(outer_diameter, 4) - std::pow(inner_diameter, 4));
  p.EA = youngs_modulus * area;
  p.EI = youngs_modulus * second_moment;
  p.mass_per_length = density * area;
  return p;
}

double LineProperties::wallArea() const { return externalArea() - internalArea(); }
double LineProperties::internalArea() const { return M_PI / 4.0 * inner_diameter * inner_diameter; }
double LineProperties::externalArea() const { return M_PI / 4.0 * outer_diameter * outer_diameter; }

}  // namespace riser_sim
