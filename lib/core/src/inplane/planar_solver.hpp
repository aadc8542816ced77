// PlanarSolver (core/inplane/planar.hpp) forwards to the private PlanarEngine.
#pragma once
#include <memory>

#include "planar_engine.hpp"

namespace vibrofric {
template <class Real>
PlanarSolver<Real>::PlanarSolver(const Waveform<Real>* normal, const Real& gamma, const Waveform<Real>& in_plane,
                                 const Real& beta, const PlanarDrive<Real>& drive, const Options& opt)
    : engine_(std::make_unique<detail::PlanarEngine<Real>>(normal, gamma, in_plane, beta, drive, opt)) {}
template <class Real>
PlanarSolver<Real>::~PlanarSolver() = default;
template <class Real>
PlanarSolver<Real>::PlanarSolver(PlanarSolver&&) noexcept = default;
template <class Real>
PlanarSolver<Real>& PlanarSolver<Real>::operator=(PlanarSolver&&) noexcept = default;
template <class Real>
std::array<Real, 2> PlanarSolver<Real>::period(const std::array<Real, 2>& s, PlanarResult<Real>* record) const {
  return engine_->period(s, record);
}
template <class Real>
PlanarResult<Real> PlanarSolver<Real>::solve() const { return engine_->solve(); }
template <class Real>
std::array<Real, 3> PlanarSolver<Real>::at(const PlanarSpan<Real>& span, const Real& phi) const {
  return engine_->at(span, phi);
}
}  // namespace vibrofric
