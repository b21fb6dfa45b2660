#include "raytrace/RowShading.h"

#include <algorithm>

namespace ivshadow::detail {

void RowShading::traceShadows() {
  answers.resize(queries.size());
  if (queries.empty()) return;
  const CasterScene* first = queryCasters.front();
  if (std::all_of(queryCasters.begin(), queryCasters.end(),
                  [first](const CasterScene* c) { return c == first; })) {
    first->transmittances(queries.data(), queries.size(), answers.data());
    return;
  }
  // Several groups' casters: each answers its own queries.
  done_.clear();
  for (const CasterScene* casters : queryCasters) {
    if (std::find(done_.begin(), done_.end(), casters) != done_.end()) continue;
    done_.push_back(casters);
    someQueries_.clear();
    for (std::size_t i = 0; i < queries.size(); ++i)
      if (queryCasters[i] == casters) someQueries_.push_back(queries[i]);
    someAnswers_.resize(someQueries_.size());
    casters->transmittances(someQueries_.data(), someQueries_.size(), someAnswers_.data());
    std::size_t next = 0;
    for (std::size_t i = 0; i < queries.size(); ++i)
      if (queryCasters[i] == casters) answers[i] = someAnswers_[next++];
  }
}

bool RowShading::asksAgain(const std::vector<CasterScene::Query>& keptQueries,
                           const std::vector<const CasterScene*>& keptCasters) const {
  if (keptQueries.size() != queries.size() || keptCasters != queryCasters) return false;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const CasterScene::Query& a = keptQueries[i];
    const CasterScene::Query& b = queries[i];
    if (a.from != b.from || a.normal != b.normal || a.to != b.to || a.model != b.model ||
        a.directional != b.directional)
      return false;
  }
  return true;
}

}  // namespace ivshadow::detail
