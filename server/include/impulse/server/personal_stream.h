#pragma once
/// One subscriber's own snapshots (docs/networked-play.md): only the bodies
/// in its area of interest, with those entering and leaving it, and under a
/// bandwidth budget the most important states first.
///
/// The stream decides what goes out; the SnapshotBuilder writes it. A
/// subscriber with neither an area nor a budget takes the room's shared
/// snapshots instead.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "impulse/server/interest_area.h"
#include "impulse/server/world_changes.h"

namespace impulse::server {

/// Joints or fields a personal snapshot adds (entering the area, or
/// changed) and removes (gone, or out of the area), by id.
struct LinkChanges {
  std::vector<std::uint32_t> described{};
  std::vector<std::uint32_t> removed{};
};

/// What one personal delta carries besides the meta.
struct PersonalDelta {
  std::vector<std::uint32_t> removed;    ///< known bodies the world removed
  std::vector<std::uint32_t> leftWorld;  ///< of those, the ones that left the world
  std::vector<std::uint32_t> leftArea;   ///< known bodies now outside the area
  std::vector<std::uint32_t> described;  ///< entering, or described again
  std::vector<std::uint32_t> states;     ///< states that go out whatever the budget
  /// Under a budget: the most important of the states waiting, highest
  /// first (at most as many as the budget could carry), sent while the
  /// budget lasts (then reported with markSent()).
  std::vector<std::uint32_t> ranked;
  /// Joints with a body in the area; fields reaching into it.
  LinkChanges joints;
  LinkChanges fields;
};

class PersonalStream {
 public:
  /// None: the whole room.
  void setArea(std::optional<AABB> area) { area_ = area; }
  /// None: no budget.
  void setBudget(std::optional<double> bytesPerSecond);
  /// Neither an area nor a budget: the room's shared snapshots will do.
  bool wantsShared() const { return !area_ && !budget_; }
  /// The client holds the room's shared picture (it took shared snapshots
  /// until now): the next snapshot must be a full one.
  bool startsOver() const { return startsOver_; }
  void startOver() { startsOver_ = true; }

  /// The ids of a full snapshot's bodies (those inside the area, ascending),
  /// which the client then holds; nothing waits any more. Its joints and
  /// fields are then knownJoints() and knownFields().
  const std::vector<std::uint32_t>& planFull(const BodyPlaces& places);
  const std::vector<std::uint32_t>& knownJoints() const { return knownJoints_; }
  const std::vector<std::uint32_t>& knownFields() const { return knownFields_; }
  /// What the next delta carries, ranking at most `maxRanked` waiting
  /// states. `changes` is normalised.
  const PersonalDelta& planDelta(const BodyPlaces& places, const WorldChanges& changes, std::uint64_t tick,
                                 std::size_t maxRanked);
  /// Bytes this delta may spend (none: no budget), after a refill for the
  /// ticks since the last delta at `tickHz`.
  std::optional<double> allowance(std::uint64_t tick, double tickHz);
  /// The delta carries the first `rankedSent` of its ranked states.
  void markSent(std::size_t rankedSent);
  /// A snapshot of `bytes` went out: the budget pays for it (a full
  /// snapshot too, which may leave it owing up to a second's bytes).
  void charge(std::size_t bytes);

  /// States waiting for the budget, and the ticks the oldest has waited.
  std::size_t withheldCount() const { return withheld_.size(); }
  std::uint64_t oldestWithheldTicks(std::uint64_t tick) const;

 private:
  struct Withheld {
    std::uint32_t id = 0;
    std::uint64_t since = 0;  ///< tick its first unsent change was seen
    double priority = 0;      ///< accumulated: grows each delta it waits
    bool sent = false;        ///< markSent()'s mark, dropped at once
  };
  /// How much a waiting state matters now: more near the area's centre and
  /// when fast, between 1 and 4; added up over the deltas it waits.
  double weight(const BodyPlace& place) const;
  /// Adds each waiting state's weight and ranks the `count` highest.
  void rank(const BodyPlaces& places, std::size_t count);
  /// The `changed` states (ascending) wait too, from `tick` if they did
  /// not already; those of bodies outside the area or described again go.
  void updateWithheld(const std::vector<std::uint32_t>& changed, const std::vector<std::uint32_t>& redescribed,
                      std::uint64_t tick);
  /// The joints and fields the area holds now (after known_ was updated),
  /// against those the client holds; `addedJoints` and `addedFields` were
  /// described again by the world (ascending).
  void planLinks(const BodyPlaces& places, const std::vector<std::uint32_t>& addedJoints,
                 const std::vector<std::uint32_t>& addedFields);

  std::optional<AABB> area_;
  std::optional<double> budget_;
  bool startsOver_ = true;
  /// The bodies the client holds, ascending.
  std::vector<std::uint32_t> known_;
  std::vector<std::uint32_t> inside_;
  std::vector<std::uint32_t> knownJoints_;
  std::vector<std::uint32_t> knownFields_;
  /// planLinks()'s scratch lists.
  std::vector<std::uint32_t> linksNow_;
  PersonalDelta delta_;
  /// By id, ascending: every pass over them is a merge with another
  /// ascending list (the changes, the area's bodies, their places), not a
  /// lookup per state; 16 subscribers of 10 000 changing bodies pass over
  /// 160 000 of them every snapshot.
  std::vector<Withheld> withheld_;
  std::vector<Withheld> withheldScratch_;
  /// rank()'s scratch list: (minus the priority, index in withheld_); and
  /// where in withheld_ delta_.ranked's states are.
  std::vector<std::pair<double, std::uint32_t>> ranking_;
  std::vector<std::uint32_t> rankedAt_;
  /// Bytes the budget holds for the next delta (negative: owed).
  double bucket_ = 0;
  std::optional<std::uint64_t> refilledAt_;
};

}  // namespace impulse::server
