#include "impulse/server/personal_stream.h"

#include <algorithm>
#include <iterator>
#include <limits>

namespace impulse::server {

namespace {

/// The most a budget may save up between deltas: a quarter second's bytes,
/// so a quiet spell is not followed by a burst past the link's rate.
constexpr double kBurstSeconds = 0.25;
/// The first delta's share of a new budget.
constexpr double kFirstShareSeconds = 0.1;
/// The most a budget may owe (a full snapshot larger than this is partly
/// forgiven): states flow again within a second of any full snapshot.
constexpr double kMostOwedSeconds = 1;
/// A waiting body this fast (m/s) or faster weighs twice a still one.
constexpr double kFastSpeed = 10;

using Ids = std::vector<std::uint32_t>;

template <class Id>
Ids valuesOf(const std::vector<Id>& ids) {
  Ids values;
  values.reserve(ids.size());
  for (const Id id : ids) values.push_back(id.value);
  return values;
}

Ids difference(const Ids& a, const Ids& b) {
  Ids out;
  std::ranges::set_difference(a, b, std::back_inserter(out));
  return out;
}

Ids intersection(const Ids& a, const Ids& b) {
  Ids out;
  std::ranges::set_intersection(a, b, std::back_inserter(out));
  return out;
}

Ids setUnion(const Ids& a, const Ids& b) {
  Ids out;
  std::ranges::set_union(a, b, std::back_inserter(out));
  return out;
}

/// `now` against `known` (both ascending): what the client must be sent
/// (new to it, or among `added`, changed) and told to drop; `known`
/// becomes `now`.
void planLinkChanges(Ids& known, Ids& now, const Ids& added, LinkChanges& changes) {
  changes.described = setUnion(difference(now, known), intersection(intersection(now, known), added));
  changes.removed = difference(known, now);
  known.swap(now);
}

AABB wholeRoom() {
  const Real far = std::numeric_limits<Real>::max();
  return {Vec2(-far, -far), Vec2(far, far)};
}

}  // namespace

void PersonalStream::setBudget(std::optional<double> bytesPerSecond) {
  budget_ = bytesPerSecond;
  bucket_ = 0;
  refilledAt_.reset();
  // Without a budget nothing waits: the next delta must carry what did.
  if (!budget_ && !withheld_.empty()) startOver();
}

const std::vector<std::uint32_t>& PersonalStream::planFull(const BodyPlaces& places) {
  places.inside(area_.value_or(wholeRoom()), known_);
  places.jointsOf(known_, knownJoints_);
  places.fieldsIn(area_, knownFields_);
  withheld_.clear();
  startsOver_ = false;
  return known_;
}

void PersonalStream::planLinks(const BodyPlaces& places, const Ids& addedJoints, const Ids& addedFields) {
  places.jointsOf(known_, linksNow_);
  planLinkChanges(knownJoints_, linksNow_, addedJoints, delta_.joints);
  places.fieldsIn(area_, linksNow_);
  planLinkChanges(knownFields_, linksNow_, addedFields, delta_.fields);
}

const PersonalDelta& PersonalStream::planDelta(const BodyPlaces& places, const WorldChanges& changes,
                                               std::uint64_t tick, std::size_t maxRanked) {
  places.inside(area_.value_or(wholeRoom()), inside_);
  const Ids removed = valuesOf(changes.removedIds());
  const Ids entering = difference(inside_, known_);
  const Ids staying = intersection(inside_, known_);
  delta_.removed = intersection(removed, known_);
  delta_.leftWorld = intersection(valuesOf(changes.leftWorldIds()), known_);
  delta_.leftArea = difference(difference(known_, inside_), removed);
  // A body described again is sent whole: the client replaces it, state and all.
  const Ids redescribed = intersection(valuesOf(changes.addedIds()), staying);
  delta_.described = setUnion(entering, redescribed);
  delta_.states = delta_.described;
  const Ids changed = difference(intersection(valuesOf(changes.changedIds()), staying), redescribed);
  delta_.ranked.clear();
  if (!budget_) {
    delta_.states = setUnion(delta_.states, changed);
  } else {
    updateWithheld(changed, redescribed, tick);
    rank(places, maxRanked);
  }
  known_.swap(inside_);
  Ids addedFields = valuesOf(changes.addedFieldIds());
  std::ranges::sort(addedFields);
  planLinks(places, valuesOf(changes.addedJointIds()), addedFields);
  return delta_;
}

void PersonalStream::updateWithheld(const Ids& changed, const Ids& redescribed, std::uint64_t tick) {
  // One merge of the waiting states with the changed ones, keeping the
  // bodies still inside (inside_, ascending, walked along).
  withheldScratch_.clear();
  auto waiting = withheld_.begin();
  auto change = changed.begin();
  auto in = inside_.begin();
  while (waiting != withheld_.end() || change != changed.end()) {
    const bool takeWaiting = change == changed.end() || (waiting != withheld_.end() && waiting->id <= *change);
    Withheld next = takeWaiting ? *waiting : Withheld{*change, tick, 0, false};
    if (takeWaiting && change != changed.end() && *change == waiting->id) ++change;
    if (takeWaiting) {
      ++waiting;
    } else {
      ++change;
    }
    while (in != inside_.end() && *in < next.id) ++in;
    const bool inside = in != inside_.end() && *in == next.id;
    if (inside && !std::ranges::binary_search(redescribed, next.id)) withheldScratch_.push_back(next);
  }
  withheld_.swap(withheldScratch_);
}

double PersonalStream::weight(const BodyPlace& place) const {
  const double fast = std::min(double(place.velocity.norm()) / kFastSpeed, 1.0);
  double near = 0;
  if (area_) {
    const Vec2 centre = (area_->lower + area_->upper) / 2;
    const double halfDiagonal = (area_->upper - area_->lower).norm() / 2;
    near = 1 - std::min(double((place.centre - centre).norm()) / halfDiagonal, 1.0);
  }
  return (1 + near) * (1 + fast);
}

void PersonalStream::rank(const BodyPlaces& places, std::size_t count) {
  ranking_.clear();
  // Both ascending by id: the places are walked along, not searched.
  auto place = places.places().begin();
  const auto end = places.places().end();
  for (Withheld& waiting : withheld_) {
    while (place != end && place->id < waiting.id) ++place;
    if (place != end && place->id == waiting.id) waiting.priority += weight(*place);
    ranking_.emplace_back(-waiting.priority, std::uint32_t(&waiting - withheld_.data()));
  }
  // Highest priority first; equal ones by id (withheld_ is by id), so a run
  // is repeatable. Only
  // the few the budget can carry need an order.
  const auto top = ranking_.begin() + std::ptrdiff_t(std::min(count, ranking_.size()));
  std::ranges::nth_element(ranking_, top);
  std::sort(ranking_.begin(), top);
  rankedAt_.clear();
  for (auto it = ranking_.begin(); it != top; ++it) {
    rankedAt_.push_back(it->second);
    delta_.ranked.push_back(withheld_[it->second].id);
  }
}

std::optional<double> PersonalStream::allowance(std::uint64_t tick, double tickHz) {
  if (!budget_) return std::nullopt;
  const double saved = refilledAt_ ? *budget_ * double(tick - *refilledAt_) / tickHz : *budget_ * kFirstShareSeconds;
  bucket_ = std::min(bucket_ + saved, *budget_ * kBurstSeconds);
  refilledAt_ = tick;
  return bucket_;
}

void PersonalStream::markSent(std::size_t rankedSent) {
  // Marked where rank() found them, then dropped in one pass.
  for (std::size_t i = 0; i < rankedSent && i < rankedAt_.size(); ++i) withheld_[rankedAt_[i]].sent = true;
  std::erase_if(withheld_, [](const Withheld& waiting) { return waiting.sent; });
}

void PersonalStream::charge(std::size_t bytes) {
  if (budget_) bucket_ = std::max(bucket_ - double(bytes), -*budget_ * kMostOwedSeconds);
}

std::uint64_t PersonalStream::oldestWithheldTicks(std::uint64_t tick) const {
  std::uint64_t oldest = 0;
  for (const Withheld& waiting : withheld_) oldest = std::max(oldest, tick - waiting.since);
  return oldest;
}

}  // namespace impulse::server
