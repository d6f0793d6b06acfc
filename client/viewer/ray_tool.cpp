#include "ray_tool.h"

#include "impulse/client/number_format.h"
#include "impulse/wire/convert.h"

namespace impulse::viewer {

namespace {

// Shorter rays are not cast: a press not yet dragged is no ray.
constexpr Real kShortestRay = Real(1e-3);

std::optional<RayHit> closestHit(const v1::QueryResult& result) {
  if (result.hits_size() == 0) return std::nullopt;
  const v1::QueryHit& hit = result.hits(0);
  return RayHit{hit.body_id(), hit.shape_id(), wire::vecFromWireUnchecked(hit.point()),
                wire::vecFromWireUnchecked(hit.normal()), hit.fraction()};
}

}  // namespace

void RayTool::aim(const Ray& ray) { aimed_ = ray; }

std::optional<Ray> RayTool::request(double now) {
  if (!aimed_ || inFlight_ || (aimed_->end - aimed_->origin).norm() < kShortestRay)
    return std::nullopt;
  const bool answeredAsAimed = answer_ && answer_->ray == *aimed_;
  if (answeredAsAimed && now - askedAt_ < kRecastInterval) return std::nullopt;
  inFlight_ = Cast{*aimed_, generation_};
  askedAt_ = now;
  return aimed_;
}

std::optional<std::string> RayTool::answered(const v1::ServerMessage& reply) {
  if (!inFlight_) return std::nullopt;
  const Cast cast = *inFlight_;
  inFlight_.reset();
  if (cast.generation != generation_) return std::nullopt;
  if (reply.has_query_result()) {
    answer_ = RayAnswer{cast.ray, closestHit(reply.query_result())};
    return std::nullopt;
  }
  answer_.reset();
  // The ray is not asked again until it moves: a refusal would repeat.
  aimed_.reset();
  return reply.has_command_result() ? reply.command_result().error() : "unexpected reply";
}

void RayTool::clear() {
  aimed_.reset();
  answer_.reset();
  ++generation_;
}

RayFigure rayFigure(const RayAnswer& answer, Real normalLength) {
  RayFigure figure;
  figure.origin = answer.ray.origin;
  figure.end = answer.ray.end;
  figure.reach = answer.ray.end;
  if (!answer.hit) return figure;
  const RayHit& hit = *answer.hit;
  figure.hit = true;
  figure.reach = hit.point;
  figure.normalTip = hit.point + normalLength * hit.normal;
  // Barbs a third of the arrow back from the tip, half that to either side.
  const Vec2 back = -normalLength / 3 * hit.normal;
  const Vec2 side(-back.y() / 2, back.x() / 2);
  figure.barbs = {figure.normalTip + back + side, figure.normalTip + back - side};
  return figure;
}

std::string describeRay(const RayAnswer& answer) {
  if (!answer.hit) return "miss";
  const RayHit& hit = *answer.hit;
  return "body " + std::to_string(hit.body) + ", shape " + std::to_string(hit.shape) + " at " +
         client::formatNumber(hit.fraction, 3) + " of the ray";
}

}  // namespace impulse::viewer
