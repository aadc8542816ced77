// InPlaneSolver (core/inplane/inplane.hpp) forwards to the private InPlaneEngine.
#pragma once
#include <memory>

#include "inplane_engine.hpp"

namespace vibrofric {
template <class Real>
InPlaneSolver<Real>::InPlaneSolver(const Waveform<Real>* normal, const Real& gamma, const Waveform<Real>& in_plane,
                                   const Real& beta, const InPlaneDrive<Real>& drive, const Options& opt)
    : engine_(std::make_unique<detail::InPlaneEngine<Real>>(normal, gamma, in_plane, beta, drive, opt)) {}
template <class Real>
InPlaneSolver<Real>::~InPlaneSolver() = default;
template <class Real>
InPlaneSolver<Real>::InPlaneSolver(InPlaneSolver&&) noexcept = default;
template <class Real>
InPlaneSolver<Real>& InPlaneSolver<Real>::operator=(InPlaneSolver&&) noexcept = default;
template <class Real>
Real InPlaneSolver<Real>::period(const Real& s, InPlaneResult<Real>* record) const {
  return engine_->period(s, record);
}
template <class Real>
InPlaneResult<Real> InPlaneSolver<Real>::solve() const { return engine_->solve(); }
template <class Real>
const std::vector<InPlaneSegment<Real>>& InPlaneSolver<Real>::segments() const { return engine_->segments(); }
template <class Real>
std::array<Real, 3> InPlaneSolver<Real>::at(const InPlaneSpan<Real>& span, const Real& phi) const {
  return engine_->at(span, phi);
}
}  // namespace vibrofric
