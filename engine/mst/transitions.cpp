// transitions.cpp: MstBridgeUpdateContacts (the guide's loop) and
// MstHandleTransitions (hello: McdHello; goodbye: the contact group goes,
// then McdGoodbye).
#include "mst_internal.h"

extern "C" {

void MEAPI MstHandleTransitions(McdModelPairContainer *pairs) {
  ME_REQUIRE_ARG(pairs != nullptr, "MstHandleTransitions", "container is NULL");
  for (int i = pairs->goodbyeFirst; i < pairs->goodbyeEnd; ++i) {
    McdModelPair *p = pairs->array[i];
    if (p->responseData) {
      MdtContactGroupDestroy(static_cast<MdtContactGroupID>(p->responseData));
      p->responseData = nullptr;
    }
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
  McdSpacePairIterator iter;
  McdSpacePairIteratorBegin(space, &iter);
  int overflow;
  do {
    McdModelPairContainerReset(b->pairs);
    overflow = McdSpaceGetPairs(space, &iter, b->pairs);
    MstHandleTransitions(b->pairs);
    MstHandleCollisions(b->pairs, space, world, b);
  } while (overflow);
  McdSpaceBeginChanges(space);
}

}  // extern "C"
