#include "parallel/element_groups.hpp"

namespace hocav {

ElementGroups single_element_groups(Index element_count) {
  ElementGroups groups;
  groups.count = element_count;
  groups.group_of.resize(static_cast<std::size_t>(element_count));
  for (Index k = 0; k < element_count; ++k) groups.group_of[k] = k;
  return groups;
}

template <int D>
ElementGroups neighbouring_element_groups(const Mesh<D>& mesh) {
  ElementGroups groups;
  groups.group_of.assign(static_cast<std::size_t>(mesh.element_count()), kNoIndex);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    if (groups.group_of[k] != kNoIndex) continue;
    Index first_neighbor = kNoIndex;
    bool started = false;
    for (int face = 0; face <= D; ++face) {
      const Index other = mesh.neighbor(k, face);
      if (other == kNoIndex) continue;
      if (first_neighbor == kNoIndex) first_neighbor = other;
      if (groups.group_of[other] != kNoIndex) continue;
      if (!started) groups.group_of[k] = groups.count++;
      started = true;
      groups.group_of[other] = groups.group_of[k];
    }
    if (!started) groups.group_of[k] = first_neighbor != kNoIndex ? groups.group_of[first_neighbor] : groups.count++;
  }
  return groups;
}

template ElementGroups neighbouring_element_groups(const Mesh<2>&);
template ElementGroups neighbouring_element_groups(const Mesh<3>&);

}  // namespace hocav
