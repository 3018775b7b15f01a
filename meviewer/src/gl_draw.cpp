/* gl_draw.cpp: one frame in fixed-function OpenGL.
 *
 * 3D pass: perspective projection, the camera's world-to-camera TM as the
 * modelview, each graphic's TM multiplied on (a Karma TM in memory is
 * OpenGL's column-major layout). Lighting: the model ambient is the
 * context's ambient colour (0 when off); lights 0 and 1 are the
 * directional lights (position (-direction, 0)), light 2 the point light
 * with its attenuation, all given in world coordinates each frame. Both
 * faces are lit. Alpha does not make 3D objects transparent (the guide's
 * own example draws a sphere with alpha 0).
 * 2D pass: orthographic R_2D_WIDTH x R_2D_HEIGHT units with y down, no
 * depth test, unlit, alpha-blended (text uses the font's alpha). */
#include "gl_draw.h"

#include <GL/gl.h>

#include <algorithm>

namespace karma::viewer {
namespace {

void Upload(Texture &t, bool mipmaps) {
  if (t.state != TextureState::Loaded || t.glName) return;
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  if (mipmaps) glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const GLenum format = t.image.channels == 4 ? GL_RGBA : GL_RGB;
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), t.image.width, t.image.height, 0, format, GL_UNSIGNED_BYTE,
               t.image.pixels.data());
  t.glName = name;
}

/* The GL texture for an ID, or 0 (untextured). */
GLuint TextureFor(RRender *rc, int id) {
  RRenderPrivate *p = rc->m_pPrivate;
  if (id == kFontTextureID) return p->font.glName;
  if (id < 0 || std::size_t(id) >= p->textures.size()) return 0;
  return p->textures[std::size_t(id)].glName;
}

void Light4(GLenum light, GLenum what, const float rgb[3], float w = 1) {
  const GLfloat v[4] = {rgb[0], rgb[1], rgb[2], w};
  glLightfv(light, what, v);
}

void ApplyLights(RRender *rc) {
  RRenderPrivate *p = rc->m_pPrivate;
  /* The structures are copied at the first frame and whenever forced. */
  if (!p->lightsApplied || rc->m_bForceDirectLight1Update) p->appliedDirect1 = rc->m_DirectLight1;
  if (!p->lightsApplied || rc->m_bForceDirectLight2Update) p->appliedDirect2 = rc->m_DirectLight2;
  if (!p->lightsApplied || rc->m_bForcePointLightUpdate) p->appliedPoint = rc->m_PointLight;
  rc->m_bForceDirectLight1Update = rc->m_bForceDirectLight2Update = rc->m_bForcePointLightUpdate = 0;
  p->lightsApplied = true;

  const GLfloat ambient[4] = {rc->m_bUseAmbientLight ? rc->m_rgbAmbientLightColor[0] : 0.0f,
                              rc->m_bUseAmbientLight ? rc->m_rgbAmbientLightColor[1] : 0.0f,
                              rc->m_bUseAmbientLight ? rc->m_rgbAmbientLightColor[2] : 0.0f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const RDirectLight *d[2] = {&p->appliedDirect1, &p->appliedDirect2};
  for (int i = 0; i < 2; ++i) {
    const GLenum l = GLenum(GL_LIGHT0 + i);
    if (!d[i]->m_bUseLight) {
      glDisable(l);
      continue;
    }
    glEnable(l);
    Light4(l, GL_AMBIENT, d[i]->m_rgbAmbient);
    Light4(l, GL_DIFFUSE, d[i]->m_rgbDiffuse);
    Light4(l, GL_SPECULAR, d[i]->m_rgbSpecular);
    const float towards[3] = {-d[i]->m_Direction[0], -d[i]->m_Direction[1], -d[i]->m_Direction[2]};
    Light4(l, GL_POSITION, towards, 0);
  }
  const RPointLight &pl = p->appliedPoint;
  if (!pl.m_bUseLight) {
    glDisable(GL_LIGHT2);
  } else {
    glEnable(GL_LIGHT2);
    Light4(GL_LIGHT2, GL_AMBIENT, pl.m_rgbAmbient);
    Light4(GL_LIGHT2, GL_DIFFUSE, pl.m_rgbDiffuse);
    Light4(GL_LIGHT2, GL_SPECULAR, pl.m_rgbSpecular);
    Light4(GL_LIGHT2, GL_POSITION, pl.m_Position, 1);
    glLightf(GL_LIGHT2, GL_CONSTANT_ATTENUATION, std::max(0.0f, pl.m_AttenuationConstant));
    glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, std::max(0.0f, pl.m_AttenuationLinear));
    glLightf(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, std::max(0.0f, pl.m_AttenuationQuadratic));
  }
}

void DrawGraphic(RRender *rc, RGraphic *g, bool is2D) {
  RObjectHeader *h = g->m_pObject;
  if (h->m_nNumVertices < 3) return;
  if (g->m_pLWMatrix) std::copy(&g->m_pLWMatrix[0][0], &g->m_pLWMatrix[0][0] + 16, &h->m_Matrix[0][0]);
  GLfloat m[16];
  for (int i = 0; i < 16; ++i) m[i] = GLfloat((&h->m_Matrix[0][0])[i]);
  glPushMatrix();
  glMultMatrixf(m);
  if (is2D) {
    glColor4fv(h->m_ColorDiffuse);
  } else {
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, h->m_ColorAmbient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, h->m_ColorDiffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, h->m_ColorSpecular);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, h->m_ColorEmissive);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, std::clamp(h->m_SpecularPower, 0.0f, 128.0f));
  }
  const GLuint texture = TextureFor(rc, h->m_nTextureID);
  if (texture) {
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture);
  } else {
    glDisable(GL_TEXTURE_2D);
  }
  glPolygonMode(GL_FRONT_AND_BACK, h->m_bIsWireFrame ? GL_LINE : GL_FILL);
  const int n = std::min(h->m_nNumVertices, g->m_nMaxNumVertices) / 3 * 3;
  const RObjectVertex *v = g->m_pVertices;
  glVertexPointer(3, GL_FLOAT, sizeof(RObjectVertex), &v->m_X);
  glNormalPointer(GL_FLOAT, sizeof(RObjectVertex), &v->m_NX);
  glTexCoordPointer(2, GL_FLOAT, sizeof(RObjectVertex), &v->m_U);
  glDrawArrays(GL_TRIANGLES, 0, n);
  glPopMatrix();
}

void DrawNativeLines(RRender *rc) {
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  for (RNativeLine *l = rc->m_pNL_First; l; l = l->m_pNext) {
    glPushMatrix();
    if (l->m_pMatrix) {
      GLfloat m[16];
      for (int i = 0; i < 16; ++i) m[i] = GLfloat(l->m_pMatrix[i / 4][i % 4]);
      glMultMatrixf(m);
    }
    glColor4fv(l->m_Color);
    glBegin(GL_LINES);
    glVertex3f(float(l->m_Start[0]), float(l->m_Start[1]), float(l->m_Start[2]));
    glVertex3f(float(l->m_End[0]), float(l->m_End[1]), float(l->m_End[2]));
    glEnd();
    glPopMatrix();
  }
}

}  // namespace

void DrawSceneGL(RRender *rc) {
  RRenderPrivate *p = rc->m_pPrivate;
  for (Texture &t : p->textures) Upload(t, true);
  Upload(p->font, false);

  glViewport(0, 0, rc->m_nWidth, rc->m_nHeight);
  glClearColor(rc->m_BackgroundColour[0], rc->m_BackgroundColour[1], rc->m_BackgroundColour[2], 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  /* 3D */
  GLfloat m[16];
  RCameraUpdate(rc);
  PerspectiveMatrix(rc, m);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(m);
  CameraMatrixFloat(rc, m);
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(m);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_LIGHTING);
  ApplyLights(rc);
  for (RGraphic *g = rc->m_pRG_First; g; g = g->m_pNext) DrawGraphic(rc, g, false);
  DrawNativeLines(rc);

  /* 2D */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, R_2D_WIDTH, R_2D_HEIGHT, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (RGraphic *g = rc->m_pRG_First2D; g; g = g->m_pNext) DrawGraphic(rc, g, true);
  for (RGraphic *g : PerformanceBarOverlay(rc)) {
    DrawGraphic(rc, g, true);
    RGraphicDestroy(g);
  }
  for (RGraphic *g : AccuracyOverlay(rc)) {
    DrawGraphic(rc, g, true);
    RGraphicDestroy(g);
  }
  for (RGraphic *g : HelpOverlay(rc)) {
    DrawGraphic(rc, g, true);
    RGraphicDestroy(g);
  }
  for (RGraphic *g : MenuOverlay(rc)) {
    DrawGraphic(rc, g, true);
    RGraphicDestroy(g);
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glFinish();
}

}  // namespace karma::viewer
