// Largest stable step of an explicit scheme, from the spectrum of the linearised line: Ritz values of
// J = ∂(q', v')/∂(q, v) (Arnoldi on finite-difference products J x), each held against the scheme's
// stability region along its own direction. Damping gives real negative eigenvalues -c/m that a
// frequency alone misses (RK4 reaches 2.785 on the real axis, 2.828 on the imaginary one); at small
// segments the structural damping, scaling like c/(m d³), sets the limit.
#pragma once
#include <complex>
#include <functional>
#include <vector>

#include "riser_sim/types.h"

namespace riser_sim {

using Complex = std::complex<double>;

// Ritz values of the dim x dim operator jv (out = J x) from a Krylov space of size krylov.
std::vector<Complex> ritzValues(int dim, int krylov, const std::function<void(const VecX&, VecX&)>& jv);

// Radius r of the stability region {z : |R(z)| <= 1} along z = r e^{i theta} (first exit from 0).
double stabilityRadius(const std::function<Complex(Complex)>& R, double theta);

// Largest h with h λ inside the stability region of R for every λ (λ with Re λ > 0, growing modes
// that no step stabilises, are held against the imaginary axis). Infinity for no λ.
double largestStableStep(const std::vector<Complex>& eigenvalues, const std::function<Complex(Complex)>& R);

}  // namespace riser_sim
