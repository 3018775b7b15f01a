/* McdModelPair.h: pairs of models and containers of pairs.
 *
 * A pair is what the farfield reports for two models whose AABBs overlap,
 * and what the nearfield tests. Its life: McdHello (caches the interaction
 * for the two geometry types), any number of McdIntersect, McdGoodbye (frees
 * what the interaction cached). The pair keeps the models in the order
 * given; the dispatcher handles an interaction written the other way round.
 *
 * Public members: model1, model2, userData (the application's) and
 * responseData (the bridge's: its contact group). The m_ members are the
 * framework's (the interaction cached at hello) and the space's. */
#ifndef KARMA_MCDMODELPAIR_H
#define KARMA_MCDMODELPAIR_H
#include "MeCall.h"
#include "MePrecision.h"
#include "McdModel.h"

ME_EXTERN_C_BEGIN

struct McdInteractions;

/* What the application asks of the pair's McdIntersect calls. The guide
 * names the request ("the pair's McdRequest values", read at McdHello) but
 * gives none of its fields; this one has the contact cap:
 *   contactMaxCount  > 0: McdIntersect reports at most this many contacts,
 *                    fewer when the result's own contactMaxCount is lower;
 *                    0: no cap of its own (the result's cap alone). */
typedef struct McdRequest {
  int contactMaxCount;
} McdRequest;

typedef struct McdModelPair {
  McdModelID model1;
  McdModelID model2;
  void *userData;
  void *responseData;
  /* private: the framework's */
  const struct McdInteractions *m_interaction; /* cached by McdHello, kept to McdGoodbye */
  void *m_cachedData;                          /* the interaction's own */
  int m_helloed;                               /* 1 between hello and goodbye */
  /* private: the space's */
  void *m_spaceData;
  int m_spaceIndex;
  /* private: McdModelPairSetRequestPtr's */
  McdRequest *m_request;
  /* private: McdIntersect's memory of the last contacts (contact reuse) */
  void *m_contactMemory;
} McdModelPair;
typedef McdModelPair *McdModelPairID;

/* A pair of two models (neither NULL, distinct), from MeMemoryAPI; NULL with
 * a warning otherwise. Call McdHello before testing it. */
MEPUBLIC McdModelPairID MEAPI McdModelPairCreate(McdModelID model1, McdModelID model2);
/* Frees a pair (calling McdGoodbye first if it is between hello and
 * goodbye). NULL is ignored. */
MEPUBLIC void MEAPI McdModelPairDestroy(McdModelPairID pair);
/* Re-targets a pair (not between hello and goodbye: warns and ignores). */
MEPUBLIC void MEAPI McdModelPairReset(McdModelPairID pair, McdModelID model1, McdModelID model2);
/* The pair keeps the pointer (the request must outlive the pair's use;
 * NULL removes it; McdModelPairReset clears it). Not between McdHello and
 * McdGoodbye (the guide's rule): a call there warns and is ignored, as does
 * one with a negative contactMaxCount. */
MEPUBLIC void MEAPI McdModelPairSetRequestPtr(McdModelPairID pair, McdRequest *request);
/* The request set on the pair, NULL if none. */
MEPUBLIC McdRequest *MEAPI McdModelPairGetRequestPtr(McdModelPairID pair);
MEPUBLIC void MEAPI McdModelPairSetUserData(McdModelPairID pair, void *data);
MEPUBLIC void *MEAPI McdModelPairGetUserData(McdModelPairID pair);

/* A container of pair pointers, filled by McdSpaceGetPairs. Its array of
 * `size` slots holds three blocks, always in this order:
 *
 *   0 = goodbyeFirst <= goodbyeEnd <= helloFirst <= helloEnd
 *                                  == stayingFirst <= stayingEnd <= size
 *
 *   [goodbyeFirst, goodbyeEnd)  goodbye pairs, filled upwards from 0
 *   [helloFirst, helloEnd)      hello pairs, filled DOWNWARDS (helloFirst
 *                               decreases; the guide's code inserts one by
 *                               `pairs->helloFirst--` and
 *                               `pairs->array[pairs->helloFirst] = pair`)
 *   [stayingFirst, stayingEnd)  staying pairs, filled upwards
 *
 * so the pairs to test, hello and staying, are the one run
 * [helloFirst, stayingEnd). McdModelPairContainerReset empties every block
 * and puts the hello/staying split in the middle: helloFirst = helloEnd =
 * stayingFirst = stayingEnd = (size + 1) / 2. A space may move the split
 * while filling as long as the order above holds. */
typedef struct McdModelPairContainer {
  McdModelPair **array;
  int size;
  int goodbyeFirst;
  int goodbyeEnd;
  int helloFirst;
  int helloEnd;
  int stayingFirst;
  int stayingEnd;
} McdModelPairContainer;

/* A container of `size` (> 0) slots, reset; NULL with a warning. */
MEPUBLIC McdModelPairContainer *MEAPI McdModelPairContainerCreate(int size);
MEPUBLIC void MEAPI McdModelPairContainerReset(McdModelPairContainer *container);
MEPUBLIC void MEAPI McdModelPairContainerDestroy(McdModelPairContainer *container);

ME_EXTERN_C_END
#endif /* KARMA_MCDMODELPAIR_H */
