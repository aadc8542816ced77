// RigSolver (core/dynamics/dynamics.hpp) forwards to the private RigEngine.
#pragma once
#include <memory>

#include "rig_engine.hpp"

namespace vibrofric {
template <class Real>
RigSolver<Real>::RigSolver(const Waveform<Real>& w, const Real& beta, const Real& gamma, const RigParameters<Real>& p,
                           const Options& opt)
    : engine_(std::make_unique<detail::RigEngine<Real>>(w, beta, gamma, p, opt)) {}
template <class Real>
RigSolver<Real>::~RigSolver() = default;
template <class Real>
RigSolver<Real>::RigSolver(RigSolver&&) noexcept = default;
template <class Real>
RigSolver<Real>& RigSolver<Real>::operator=(RigSolver&&) noexcept = default;
template <class Real>
RigState<Real> RigSolver<Real>::period(const State& in, RigResult<Real>* record) const {
  return engine_->period(in, record);
}
template <class Real>
std::array<Real, 3> RigSolver<Real>::at(const RigSpan<Real>& span, const Real& phi) const {
  return engine_->at(span, phi);
}
template <class Real>
std::array<Real, 2> RigSolver<Real>::normal(const RigSpan<Real>& span, const Real& phi) const {
  return engine_->normal(span, phi);
}
template <class Real>
const Real& RigSolver<Real>::damping() const { return engine_->damping(); }
template <class Real>
const Real& RigSolver<Real>::omega_squared() const { return engine_->omega_squared(); }
template <class Real>
const Contact<Real>& RigSolver<Real>::contact() const { return engine_->contact(); }
template <class Real>
RigResult<Real> RigSolver<Real>::solve() const { return engine_->solve(); }
template <class Real>
RigResult<Real> RigSolver<Real>::solve(const Real& y, const Real& v, const Real& s,
                                       const std::array<std::array<double, 3>, 3>& J) const {
  return engine_->solve(y, v, s, J);
}

}  // namespace vibrofric
