// Largest stable step of an explicit scheme, from the spectrum of the linearised line: Ritz values of
// J = ∂(q', v')/∂(q, v) (Arnoldi on finite-difference products J x), each held against the scheme's
// stability region along its own direction. Damping gives real negative eigenvalues -c/m that a
// frequency alone misses (RK4 reaches 2.785 on the real axis, 2.828 on the imaginary one); at small
// segments the structural damping, scaling like c/(m d³), sets the limit.
#pragma once
#include <complex>
#include <functional>
#include <limits>
#include <string>
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

// The linearised line at a state, for a first-order system y' = f(y) with y = [q; v; ...] (p positions,
// p velocities, anything after them ignored): the highest natural frequency ω_max [rad/s], from the Ritz
// values of A = ∂v'/∂q (|λ_max(A)| = ω_max² undamped), and the largest step of the scheme R with every
// Ritz value of ∂(q', v')/∂(q, v) inside its stability region (damping included). Forward differences
// about y; f may leave scratch state behind (the caller re-evaluates at y afterwards if it needs to).
struct LinearisedSpectrum {
  double omega_max = 0.0;                                        // [rad/s]
  double damped_step = std::numeric_limits<double>::infinity();  // [s]
};
LinearisedSpectrum linearisedSpectrum(int p, const VecX& y, const std::function<void(const VecX&, VecX&)>& f,
                                      const std::function<Complex(Complex)>& R);

// "a safe solver.dt is 0.8 x limit s, or use solver.integrator generalized_alpha / midpoint (implicit) or
// dopri5 (adaptive)": the advice when an explicit fixed-step scheme's solver.dt is above its limit [s].
std::string safeStepAdvice(double stable_step);
// Empty, or "solver.dt DT s is above SCHEME's stability limit ~H s (highest frequency W rad/s, damping
// included): <safeStepAdvice>" when dt > stable_step (explicit fixed-step schemes; the node refuses it).
std::string stepAboveLimitMessage(const std::string& scheme, double dt, double stable_step, double omega_max);
// What a diverged explicit run adds to its reason: at or above 0.9 x the limit, the limit and a safe step;
// below it, why the estimate at the initial state may not hold and what to try.
std::string divergenceStabilityNote(const std::string& scheme, double dt, double stable_step, double omega_max);

}  // namespace riser_sim
