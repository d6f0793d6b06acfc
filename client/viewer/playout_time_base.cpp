#include "playout_time_base.h"

#include <algorithm>

namespace impulse::viewer {

namespace {

// At 30 snapshots a second, 8 s of history: longer than any playout delay.
constexpr std::size_t kMaxAnchors = 256;

}  // namespace

double PlayoutTimeBase::onSnapshot(double simTime, double scale) {
  if (!(scale > 0)) scale = 1;
  // Simulated time only goes back for a new world on a new connection; start
  // over there, as the playout clock does.
  if (anchors_.empty() || simTime < anchors_.back().sim) {
    anchors_.clear();
    anchors_.push_back({simTime, simTime, scale});
    return simTime;
  }
  const Anchor& last = anchors_.back();
  // The time since the last snapshot ran at the new scale (it changes at a
  // tick's start, before that tick's steps).
  const double playout = last.playout + (simTime - last.sim) / scale;
  anchors_.push_back({playout, simTime, scale});
  if (anchors_.size() > kMaxAnchors) anchors_.pop_front();
  return playout;
}

double PlayoutTimeBase::toSim(double playout) const {
  if (anchors_.empty()) return playout;
  // The last anchor at or before `playout` (or the first one).
  const auto after = std::upper_bound(
      anchors_.begin(), anchors_.end(), playout,
      [](double p, const Anchor& anchor) { return p < anchor.playout; });
  const Anchor& from = after == anchors_.begin() ? anchors_.front() : *std::prev(after);
  // Between two snapshots the simulation ran at the later one's scale;
  // past the newest, at the newest scale.
  const double scale = after == anchors_.end() || after == anchors_.begin() ? from.scale
                                                                              : after->scale;
  return from.sim + (playout - from.playout) * scale;
}

}  // namespace impulse::viewer
