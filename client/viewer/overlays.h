#pragma once
/// The debug overlays over the scene: contact points with their normals,
/// bounding boxes and velocity vectors, each switched on its own.

#include <imgui.h>

#include <span>
#include <vector>

#include "contact_finder.h"
#include "controls.h"
#include "interpolated_world.h"
#include "view_transform.h"

namespace impulse::viewer {

class OverlayRenderer {
 public:
  void draw(ImDrawList& list, const ViewTransform& view, std::span<const DrawnBody> bodies,
            const Overlays& overlays);
  /// Contacts found in the last frame drawn with the contact overlay on.
  const std::vector<ShownContact>& contacts() const { return contacts_; }

 private:
  void drawBounds(ImDrawList& list, const ViewTransform& view, std::span<const DrawnBody> bodies);
  void drawVelocities(ImDrawList& list, const ViewTransform& view,
                      std::span<const DrawnBody> bodies);
  void drawContacts(ImDrawList& list, const ViewTransform& view, std::span<const DrawnBody> bodies);

  std::vector<ShownContact> contacts_;
};

}  // namespace impulse::viewer
