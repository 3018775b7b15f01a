/* MeViewerColor.h: colour arguments as either float[4] or MeReal[4].
 *
 * The guide declares the primitive creators with `const float color[4]`
 * (and RNLineCreate, RGraphicCreate with `const AcmeReal color[4]`), yet its own programs
 * pass both kinds: RainbowChain a float array, the basic-steps program
 * `MeReal red[]`. With MeReal = float they are the same type; with
 * KARMA_DOUBLE they are not, and the other kind would not compile in C++
 * (and warn in C). So, in a double build only:
 *   - C11: each colour-taking function name is also a macro that converts
 *     a double array to a float copy (a compound literal living for the
 *     call) through _Generic, and passes anything else through unchanged;
 *   - C++: inline overloads taking `const double color[4]` (or, for
 *     RNLineCreate and RGraphicCreate, `const float color[4]`).
 * Included by MeViewer.h after the declarations; not meant to be included
 * on its own. */
#ifndef KARMA_MEVIEWERCOLOR_H
#define KARMA_MEVIEWERCOLOR_H

#if KARMA_DOUBLE

static inline const float *RColorFromDouble_(const double *c, float *out) {
  int i;
  if (!c) return 0;
  for (i = 0; i < 4; ++i) out[i] = (float)c[i];
  return out;
}
static inline const MeReal *RColorFromFloat_(const float *c, MeReal *out) {
  int i;
  if (!c) return 0;
  for (i = 0; i < 4; ++i) out[i] = (MeReal)c[i];
  return out;
}

#  if !defined(__cplusplus) && defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#    define R_COLOR_F_(c) \
      _Generic((c), double *: RColorFromDouble_((const double *)(c), (float[4]){0, 0, 0, 0}),        \
                 const double *: RColorFromDouble_((const double *)(c), (float[4]){0, 0, 0, 0}),       \
                 default: (c))
#    define R_COLOR_R_(c) \
      _Generic((c), float *: RColorFromFloat_((const float *)(c), (MeReal[4]){0, 0, 0, 0}),          \
                 const float *: RColorFromFloat_((const float *)(c), (MeReal[4]){0, 0, 0, 0}),         \
                 default: (c))
#    define RGraphic2DRectangleCreate(rc, x, y, w, h, c) RGraphic2DRectangleCreate(rc, x, y, w, h, R_COLOR_F_(c))
#    define RGraphicGroundPlaneCreate(rc, l, t, c, y) RGraphicGroundPlaneCreate(rc, l, t, R_COLOR_F_(c), y)
#    define RGraphicBoxCreate(rc, x, y, z, c, m) RGraphicBoxCreate(rc, x, y, z, R_COLOR_F_(c), m)
#    define RGraphicConeCreate(rc, r, u, l, c, m) RGraphicConeCreate(rc, r, u, l, R_COLOR_F_(c), m)
#    define RGraphicCylinderCreate(rc, r, h, c, m) RGraphicCylinderCreate(rc, r, h, R_COLOR_F_(c), m)
#    define RGraphicSphereCreate(rc, r, c, m) RGraphicSphereCreate(rc, r, R_COLOR_F_(c), m)
#    define RGraphicSquareCreate(rc, s, c, m) RGraphicSquareCreate(rc, s, R_COLOR_F_(c), m)
#    define RGraphicTorusCreate(rc, i, o, c, m) RGraphicTorusCreate(rc, i, o, R_COLOR_F_(c), m)
#    define RGraphicFrustumCreate(rc, br, tr, b, t, s, c, m) \
      RGraphicFrustumCreate(rc, br, tr, b, t, s, R_COLOR_F_(c), m)
#    define RGraphicLineCreate(rc, o, e, c, m) RGraphicLineCreate(rc, o, e, R_COLOR_F_(c), m)
#    define RGraphicTextCreate(rc, t, x, y, c) RGraphicTextCreate(rc, t, x, y, R_COLOR_F_(c))
#    define RGraphicSetColor(g, c) RGraphicSetColor(g, R_COLOR_F_(c))
#    define RNLineCreate(rc, s, e, c, m) RNLineCreate(rc, s, e, R_COLOR_R_(c), m)
#    define RGraphicLoadASE(rc, f, x, y, z, c, m) RGraphicLoadASE(rc, f, x, y, z, R_COLOR_F_(c), m)
#    define RGraphicCreate(rc, f, x, y, z, c, m, d, k) RGraphicCreate(rc, f, x, y, z, R_COLOR_R_(c), m, d, k)
#  elif defined(__cplusplus)
#    define R_DOUBLE_COLOR_OVERLOAD_(ret, name, params, args) \
      inline ret name params {                                \
        float f_[4];                                          \
        return name args;                                     \
      }
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphic2DRectangleCreate,
                         (RRender * rc, AcmeReal x, AcmeReal y, AcmeReal w, AcmeReal h, const double c[4]),
                         (rc, x, y, w, h, RColorFromDouble_(c, f_)))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicGroundPlaneCreate,
                         (RRender * rc, AcmeReal l, int t, const double c[4], AcmeReal y),
                         (rc, l, t, RColorFromDouble_(c, f_), y))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicBoxCreate,
                         (RRender * rc, AcmeReal x, AcmeReal y, AcmeReal z, const double c[4], MeMatrix4Ptr m),
                         (rc, x, y, z, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicConeCreate,
                         (RRender * rc, AcmeReal r, AcmeReal u, AcmeReal l, const double c[4], MeMatrix4Ptr m),
                         (rc, r, u, l, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicCylinderCreate,
                         (RRender * rc, AcmeReal r, AcmeReal h, const double c[4], MeMatrix4Ptr m),
                         (rc, r, h, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicSphereCreate,
                         (RRender * rc, AcmeReal r, const double c[4], MeMatrix4Ptr m),
                         (rc, r, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicSquareCreate,
                         (RRender * rc, AcmeReal s, const double c[4], MeMatrix4Ptr m),
                         (rc, s, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicTorusCreate,
                         (RRender * rc, AcmeReal i, AcmeReal o, const double c[4], MeMatrix4Ptr m),
                         (rc, i, o, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicFrustumCreate,
                         (RRender * rc, AcmeReal br, AcmeReal tr, AcmeReal b, AcmeReal t, int s, const double c[4],
                          MeMatrix4Ptr m),
                         (rc, br, tr, b, t, s, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicLineCreate,
                         (RRender * rc, AcmeReal *o, AcmeReal *e, const double c[4], MeMatrix4Ptr m),
                         (rc, o, e, RColorFromDouble_(c, f_), m))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicTextCreate,
                         (RRender * rc, char *t, AcmeReal x, AcmeReal y, const double c[4]),
                         (rc, t, x, y, RColorFromDouble_(c, f_)))
R_DOUBLE_COLOR_OVERLOAD_(void, RGraphicSetColor, (RGraphic * g, const double c[4]), (g, RColorFromDouble_(c, f_)))
R_DOUBLE_COLOR_OVERLOAD_(RGraphic *, RGraphicLoadASE,
                         (RRender * rc, char *f, AcmeReal x, AcmeReal y, AcmeReal z, const double c[4], MeMatrix4Ptr m),
                         (rc, f, x, y, z, RColorFromDouble_(c, f_), m))
inline RGraphic *RGraphicCreate(RRender *rc, char *f, AcmeReal x, AcmeReal y, AcmeReal z, const float c[4],
                                MeMatrix4Ptr m, int is2D, int keep) {
  MeReal r[4];
  return RGraphicCreate(rc, f, x, y, z, RColorFromFloat_(c, r), m, is2D, keep);
}
inline RNativeLine *RNLineCreate(RRender *const rc, const AcmeReal s[3], const AcmeReal e[3], const float c[4],
                                 const MeVector4 *const m) {
  MeReal r[4];
  return RNLineCreate(rc, s, e, RColorFromFloat_(c, r), m);
}
#    undef R_DOUBLE_COLOR_OVERLOAD_
#  endif

#endif /* KARMA_DOUBLE */

#endif /* KARMA_MEVIEWERCOLOR_H */
