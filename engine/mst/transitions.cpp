// transitions.cpp: MstBridgeUpdateContacts (the guide's loop) and
// MstHandleTransitions (hello: McdHello; goodbye: the contact group goes,
// then McdGoodbye). The loop skips the pairs of two frozen models that stay
// (a sleeping stack's contacts): their collision is nothing, so a step
// costs the pairs that can change, not every kept pair.
#include "mst_internal.h"
#include "space/space_internal.h"

extern "C" {

void MEAPI MstHandleTransitions(McdModelPairContainer *pairs) {
  ME_REQUIRE_ARG(pairs != nullptr, "MstHandleTransitions", "container is NULL");
  for (int i = pairs->goodbyeFirst; i < pairs->goodbyeEnd; ++i) {
    McdModelPair *p = pairs->array[i];
    karma::mst::DropContactGroup(p);
    McdGoodbye(p);
  }
  for (int i = pairs->helloFirst; i < pairs->helloEnd; ++i) McdHello(pairs->array[i]);
}

void MEAPI MstBridgeUpdateContacts(MstBridgeID b, McdSpaceID space, MdtWorldID world) {
  static const char *fn = "MstBridgeUpdateContacts";
  ME_REQUIRE_ARG(b != nullptr && space != nullptr && world != nullptr, fn, "bridge, space or world is NULL");
  ME_REQUIRE_ARG(McdSpaceIsChanging(space), fn,
                 "the space is not in a change block (call McdSpaceBeginChanges after "
                 "handling its pairs); no contacts updated");
  McdSpaceEndChanges(space);
  McdSpacePairIterator iter{};  // left unwritten on a bad space
  McdSpacePairIteratorBegin(space, &iter);
  int overflow;
  do {
    McdModelPairContainerReset(b->pairs);
    // The pairs of McdSpaceGetPairs, in the same chunks, less the stayings
    // of two frozen models, which MstHandleCollisions would skip.
    overflow = karma::mcd::GetActivePairs(space, &iter, b->pairs);
    MstHandleTransitions(b->pairs);
    MstHandleCollisions(b->pairs, space, world, b);
  } while (overflow);
  McdSpaceBeginChanges(space);
}

}  // extern "C"
