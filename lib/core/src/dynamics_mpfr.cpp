// The rig dynamics solver in mpfr, compiled once (dynamics.hpp).
#include "vibrofric/core/dynamics.hpp"

namespace vibrofric {
template class RigSolver<mpfr>;
template RigResult<mpfr> solve_rig<mpfr>(const Waveform<mpfr>&, const mpfr&, const mpfr&, const RigParameters<mpfr>&,
                                         const Options&);
template RigResult<mpfr> solve_rig<mpfr>(const Waveform<mpfr>&, const mpfr&, const mpfr&, const RigParameters<mpfr>&,
                                         const RigResult<mpfr>&, const Options&);
}  // namespace vibrofric
