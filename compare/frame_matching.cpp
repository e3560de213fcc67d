// Sorted merge of two name lists.
#include "compare/frame_matching.h"

#include <algorithm>

namespace raintrace::compare {

std::vector<FramePair> match_frames(std::vector<std::string> a, std::vector<std::string> b) {
  for (auto* list : {&a, &b}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  std::vector<FramePair> pairs;
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i] < b[j])) {
      pairs.push_back({a[i++], true, false});
    } else if (i == a.size() || b[j] < a[i]) {
      pairs.push_back({b[j++], false, true});
    } else {
      pairs.push_back({a[i], true, true});
      ++i;
      ++j;
    }
  }
  return pairs;
}

}  // namespace raintrace::compare
