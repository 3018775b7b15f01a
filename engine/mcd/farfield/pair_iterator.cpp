// pair_iterator.cpp: handing the current events to the caller in chunks.
//
// Each call fills the chunk from the iterator's position: goodbyes first (so
// that the memory they hold is released first), then hellos and stayings,
// which share what is left. When both remain, each gets at least half of the
// remaining room; one takes it all once the other is exhausted. A chunk of
// size 1 therefore still makes progress. The return value is true while
// events remain: call again with the same iterator.
#include "axis_sort_space.h"

#include "MeMessage.h"

#include <algorithm>

namespace karma::mcd {

void AxisSortSpace::PairIteratorBegin(PairIterator *iter) const {
  if (!iter) {
    MeWarning(0, "McdSpacePairIteratorBegin: iterator is NULL");
    return;
  }
  *iter = PairIterator{};
  iter->generation = generation_;
}

bool AxisSortSpace::GetPairs(PairIterator *iter, PairChunk *chunk) {
  return FillChunk(iter, chunk, StayingFilter::All, "McdSpaceGetPairs");
}

bool AxisSortSpace::GetTransitions(PairIterator *iter, PairChunk *chunk) {
  return FillChunk(iter, chunk, StayingFilter::None, "McdSpaceGetTransitions");
}

// The chunks of GetPairs, each with its stayings of two frozen proxies left
// out, while goodbyes or hellos remain: the same boundaries, so the
// transitions of each chunk come before the same stayings as in GetPairs.
// Once only stayings remain, where chunks fall changes nothing for a caller
// that handles each chunk's transitions and then its pairs in order, so
// each chunk is filled with active stayings (FillActiveStayings).
bool AxisSortSpace::GetActivePairs(PairIterator *iter, PairChunk *chunk) {
  return FillChunk(iter, chunk, StayingFilter::Active, "McdSpaceGetPairs");
}

bool AxisSortSpace::FillChunk(PairIterator *iter, PairChunk *chunk, StayingFilter stayings, const char *api) {
  const bool withStaying = stayings != StayingFilter::None;
  if (!iter || !chunk || !chunk->array || chunk->size < 1) {
    MeWarning(0, "%s: NULL iterator or container, or a container of no size; no pairs", api);
    return false;
  }
  chunk->goodbyeFirst = chunk->goodbyeEnd = chunk->helloFirst = chunk->helloEnd = chunk->stayingEnd = 0;
  if (!RequireOutside(api)) return false;
  if (iter->generation != generation_) {
    MeWarning(0,
              "%s: the iterator was not begun for the current pairs (call McdSpacePairIteratorBegin "
              "after McdSpaceEndChanges); no pairs",
              api);
    return false;
  }
  const int goodbyesLeft = static_cast<int>(goodbyes_.size()) - iter->nextGoodbye;
  const int hellosLeft = static_cast<int>(hellos_.size()) - iter->nextHello;
  const int stayingsLeft = withStaying ? static_cast<int>(stayings_.size()) - iter->nextStaying : 0;
  if (stayings == StayingFilter::Active && goodbyesLeft == 0 && hellosLeft == 0) return FillActiveStayings(iter, chunk);

  const int g = std::min(goodbyesLeft, chunk->size);
  const int room = chunk->size - g;
  const int h = std::min(hellosLeft, room - std::min(stayingsLeft, room / 2));
  const int s = std::min(stayingsLeft, room - h);

  const PairRecord **out = chunk->array;
  for (int i = 0; i < g; ++i) *out++ = goodbyes_[static_cast<std::size_t>(iter->nextGoodbye + i)];
  for (int i = 0; i < h; ++i) *out++ = hellos_[static_cast<std::size_t>(iter->nextHello + i)];
  if (stayings == StayingFilter::Active) {
    if (s > 0) {  // the active ones among stayings_[nextStaying, nextStaying + s)
      BuildActiveStayings();
      const PairOrder last = stayings_[static_cast<std::size_t>(iter->nextStaying + s - 1)]->Order();
      for (auto at = ActiveFrom(iter->nextStaying); at != activeStayings_.end() && (*at)->Order() <= last; ++at)
        *out++ = *at;
    }
  } else {
    for (int i = 0; i < s; ++i) *out++ = stayings_[static_cast<std::size_t>(iter->nextStaying + i)];
  }
  iter->nextGoodbye += g;
  iter->nextHello += h;
  iter->nextStaying += s;

  chunk->goodbyeFirst = 0;
  chunk->goodbyeEnd = g;
  chunk->helloFirst = g;
  chunk->helloEnd = g + h;
  chunk->stayingEnd = static_cast<int>(out - chunk->array);
  return goodbyesLeft - g + hellosLeft - h + stayingsLeft - s > 0;
}

// The first active staying at or after stayings_[index].
std::vector<PairRecord *>::const_iterator AxisSortSpace::ActiveFrom(int index) const {
  if (index >= static_cast<int>(stayings_.size())) return activeStayings_.end();
  return std::lower_bound(activeStayings_.begin(), activeStayings_.end(), stayings_[static_cast<std::size_t>(index)],
                          [](const PairRecord *l, const PairRecord *r) { return l->Order() < r->Order(); });
}

// A chunk of stayings only: the next active stayings, as many as fit; true
// while more remain.
bool AxisSortSpace::FillActiveStayings(PairIterator *iter, PairChunk *chunk) {
  BuildActiveStayings();
  auto at = ActiveFrom(iter->nextStaying);
  const PairRecord **out = chunk->array;
  for (; at != activeStayings_.end() && out - chunk->array < chunk->size; ++at) *out++ = *at;
  // Resume at the next active staying's place in stayings_.
  iter->nextStaying = static_cast<int>(stayings_.size());
  if (at != activeStayings_.end()) {
    auto place = std::lower_bound(stayings_.begin(), stayings_.end(), *at,
                                  [](const PairRecord *l, const PairRecord *r) { return l->Order() < r->Order(); });
    iter->nextStaying = static_cast<int>(place - stayings_.begin());
  }
  chunk->goodbyeFirst = chunk->goodbyeEnd = chunk->helloFirst = chunk->helloEnd = 0;
  chunk->stayingEnd = static_cast<int>(out - chunk->array);
  return at != activeStayings_.end();
}

}  // namespace karma::mcd
