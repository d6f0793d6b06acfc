#pragma once
// Edge lists of the body graph. A two-body element (a contact; a joint
// tomorrow) is threaded through doubly linked lists of both its bodies, so a
// body finds its elements without a search. An edge key names one element
// and one side: key = index * 2 + side (side 0: bodyA, 1: bodyB). Each
// element kind keeps its own list head in the body.

#include <cstdint>
#include <vector>

namespace impulse {

inline constexpr std::int32_t kNullIndex = -1;

inline std::int32_t edgeKey(std::int32_t element, int side) { return element * 2 + side; }
inline std::int32_t edgeElement(std::int32_t key) { return key >> 1; }
inline int edgeSide(std::int32_t key) { return key & 1; }

/// The links an element kind carries (as a member named `edges`).
struct EdgeLinks {
  std::int32_t bodyA = kNullIndex;
  std::int32_t bodyB = kNullIndex;
  std::int32_t prev[2] = {kNullIndex, kNullIndex};
  std::int32_t next[2] = {kNullIndex, kNullIndex};

  /// The body at the other end of an edge.
  std::int32_t otherBody(std::int32_t key) const { return edgeSide(key) == 0 ? bodyB : bodyA; }
  std::int32_t body(int side) const { return side == 0 ? bodyA : bodyB; }
};

/// Puts side `side` of element `index` at the front of the list at `head`.
template <class Element>
void linkEdge(std::vector<Element>& elements, std::int32_t& head, std::int32_t index, int side) {
  EdgeLinks& links = elements[index].edges;
  std::int32_t key = edgeKey(index, side);
  links.prev[side] = kNullIndex;
  links.next[side] = head;
  if (head != kNullIndex) elements[edgeElement(head)].edges.prev[edgeSide(head)] = key;
  head = key;
}

/// Takes side `side` of element `index` out of the list at `head`.
template <class Element>
void unlinkEdge(std::vector<Element>& elements, std::int32_t& head, std::int32_t index, int side) {
  const EdgeLinks& links = elements[index].edges;
  std::int32_t prev = links.prev[side];
  std::int32_t next = links.next[side];
  if (prev != kNullIndex) {
    elements[edgeElement(prev)].edges.next[edgeSide(prev)] = next;
  } else {
    head = next;
  }
  if (next != kNullIndex) elements[edgeElement(next)].edges.prev[edgeSide(next)] = prev;
}

/// Calls goOn(key, element) for the edges of the list at `head` (elements
/// may be a const vector) until it returns false; returns whether every
/// edge was visited. goOn may not unlink the edge it is given.
template <class Elements, class GoOn>
bool forEachEdgeWhile(Elements& elements, std::int32_t head, GoOn&& goOn) {
  for (std::int32_t key = head; key != kNullIndex;) {
    auto& element = elements[edgeElement(key)];
    if (!goOn(key, element)) return false;
    key = element.edges.next[edgeSide(key)];
  }
  return true;
}

/// Calls visit(key, element) for each edge of the list at `head`, as
/// forEachEdgeWhile.
template <class Elements, class Visit>
void forEachEdge(Elements& elements, std::int32_t head, Visit&& visit) {
  forEachEdgeWhile(elements, head, [&](std::int32_t key, auto& element) {
    visit(key, element);
    return true;
  });
}

}  // namespace impulse
