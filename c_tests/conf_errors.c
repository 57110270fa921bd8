/*
 * conf_errors: the GL error table. Every row is one (entry point, error) pair the ES 1.1
 * specification (or the OES extension it belongs to) names: the call with the bad argument,
 * and the error it must raise. Each row runs in a fresh context on the same pbuffer:
 *
 *   - the row's setup calls (before SNAP) must raise nothing;
 *   - the bad call must raise exactly the expected error, and glGetError must then say
 *     GL_NO_ERROR (reading clears the flag);
 *   - the state a wide snapshot covers (glGet of ~120 values, every light, the material,
 *     texture environments, the bound texture's parameters, clip planes, pointers, the bound
 *     buffer and the pixels) is the same after the bad call as before it (ES 1.1 2.5: a
 *     command that raises an error has no other effect).
 *
 * Rows an extension adds run only when GL_EXTENSIONS lists it; extension functions are
 * found through eglGetProcAddress. Rows where Mesa departs from the specification run as
 * known deviations there (the `strict` column, with the reason beside the row). The first
 * error sticking until read is checked at the end. Prints the number of pairs tested.
 */
#include "common.h"

#include <math.h>

#define SW 16
#define SH 16

/* Scratch memory every pointer argument points into: large enough for any read or write
 * a row's call may make. */
static GLfloat fbuf[64];
static GLint ibuf[64];
static GLfixed xbuf[64];
static GLboolean bbuf[64];
static GLubyte ubuf[64 * 64 * 4];
static void *pbuf[4];

static GLint geti(GLenum pname)
{
    GLint v = 0;
    glGetIntegerv(pname, &v);
    return v;
}

/* Extension entry points. */
static PFNGLBLENDEQUATIONOESPROC pBlendEquation;
static PFNGLBLENDFUNCSEPARATEOESPROC pBlendFuncSeparate;
static PFNGLBLENDEQUATIONSEPARATEOESPROC pBlendEquationSeparate;
static PFNGLCURRENTPALETTEMATRIXOESPROC pCurrentPaletteMatrix;
static PFNGLMATRIXINDEXPOINTEROESPROC pMatrixIndexPointer;
static PFNGLWEIGHTPOINTEROESPROC pWeightPointer;
static PFNGLMAPBUFFEROESPROC pMapBuffer;
static PFNGLUNMAPBUFFEROESPROC pUnmapBuffer;
static PFNGLGETBUFFERPOINTERVOESPROC pGetBufferPointerv;

/* Taken again after a row's setup, so the comparison sees only the bad call. */
static void snapshot(unsigned char *out);
static unsigned char snap_before[32768];
#define SNAP snapshot(snap_before)

/* A texture object of its own, bound to unit 0. */
#define TEX                                                                              \
    GLuint tex_ = 0;                                                                     \
    glGenTextures(1, &tex_);                                                             \
    glBindTexture(GL_TEXTURE_2D, tex_)
/* ...with a 4x4 RGBA level 0. */
#define TEX_IMAGE                                                                        \
    TEX;                                                                                 \
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, ubuf)
/* A buffer object of 16 bytes bound to ARRAY_BUFFER. */
#define BUF                                                                              \
    GLuint buf_ = 0;                                                                     \
    glGenBuffers(1, &buf_);                                                              \
    glBindBuffer(GL_ARRAY_BUFFER, buf_);                                                 \
    glBufferData(GL_ARRAY_BUFFER, 16, ubuf, GL_STATIC_DRAW)

#define BAD 0x7FFF /* no GL enum has this value */
#define MP "GL_OES_matrix_palette"
#define MB "GL_OES_mapbuffer"
#define PSA "GL_OES_point_size_array"
#define PS "GL_OES_point_sprite"

/*
 * The table: X(id, expected error, extension or NULL, strict, call...).
 * strict = 1: checked only on this library; the comment says what Mesa does.
 */
#define ERRORS(X)                                                                        \
    /* --- enables and client state --- */                                              \
    X(en1, GL_INVALID_ENUM, NULL, 0, glEnable(BAD))                                      \
    X(en2, GL_INVALID_ENUM, NULL, 0, glDisable(BAD))                                     \
    /* Mesa enables client arrays through glEnable (desktop GL). */                      \
    X(en3, GL_INVALID_ENUM, NULL, 1, glEnable(GL_VERTEX_ARRAY))                          \
    X(en4, GL_INVALID_ENUM, NULL, 0, glEnable(GL_CLIP_PLANE0 + geti(GL_MAX_CLIP_PLANES))) \
    X(en5, GL_INVALID_ENUM, NULL, 0, glEnable(GL_LIGHT0 + geti(GL_MAX_LIGHTS)))          \
    X(en6, GL_INVALID_ENUM, NULL, 0, glEnableClientState(BAD))                           \
    X(en7, GL_INVALID_ENUM, NULL, 0, glDisableClientState(BAD))                          \
    X(en8, GL_INVALID_ENUM, NULL, 0, glEnableClientState(GL_LIGHTING))                   \
    X(en9, GL_INVALID_ENUM, NULL, 0, glIsEnabled(BAD))                                   \
    /* --- texture units --- */                                                         \
    /* Mesa accepts units up to its combined image-unit limit, past MAX_TEXTURE_UNITS. */ \
    X(tu1, GL_INVALID_ENUM, NULL, 1, glActiveTexture(GL_TEXTURE0 + geti(GL_MAX_TEXTURE_UNITS))) \
    X(tu2, GL_INVALID_ENUM, NULL, 0, glActiveTexture(BAD))                               \
    X(tu3, GL_INVALID_ENUM, NULL, 0,                                                     \
      glClientActiveTexture(GL_TEXTURE0 + geti(GL_MAX_TEXTURE_UNITS)))                   \
    X(tu4, GL_INVALID_ENUM, NULL, 0, glClientActiveTexture(BAD))                         \
    /* --- per-fragment state --- */                                                    \
    X(pf1, GL_INVALID_ENUM, NULL, 0, glAlphaFunc(BAD, 0.5f))                             \
    X(pf2, GL_INVALID_ENUM, NULL, 0, glAlphaFuncx(BAD, 0))                               \
    X(pf3, GL_INVALID_ENUM, NULL, 0, glBlendFunc(BAD, GL_ONE))                           \
    X(pf4, GL_INVALID_ENUM, NULL, 0, glBlendFunc(GL_ONE, BAD))                           \
    /* Mesa accepts SRC_COLOR as a source and DST_COLOR as a destination (NV_blend_square). */ \
    X(pf5, GL_INVALID_ENUM, NULL, 1, glBlendFunc(GL_SRC_COLOR, GL_ONE))                  \
    X(pf6, GL_INVALID_ENUM, NULL, 1, glBlendFunc(GL_ONE, GL_DST_COLOR))                  \
    X(pf7, GL_INVALID_ENUM, NULL, 0, glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE))         \
    X(pf8, GL_INVALID_ENUM, NULL, 0, glDepthFunc(BAD))                                   \
    X(pf9, GL_INVALID_ENUM, NULL, 0, glLogicOp(BAD))                                     \
    X(pf10, GL_INVALID_ENUM, NULL, 0, glStencilFunc(BAD, 0, 0xFF))                       \
    X(pf11, GL_INVALID_ENUM, NULL, 0, glStencilOp(BAD, GL_KEEP, GL_KEEP))                \
    X(pf12, GL_INVALID_ENUM, NULL, 0, glStencilOp(GL_KEEP, BAD, GL_KEEP))                \
    X(pf13, GL_INVALID_ENUM, NULL, 0, glStencilOp(GL_KEEP, GL_KEEP, BAD))                \
    X(pf14, GL_INVALID_ENUM, NULL, 0, glCullFace(BAD))                                   \
    X(pf15, GL_INVALID_ENUM, NULL, 0, glFrontFace(BAD))                                  \
    X(pf16, GL_INVALID_ENUM, NULL, 0, glShadeModel(BAD))                                 \
    X(pf17, GL_INVALID_ENUM, NULL, 0, glHint(BAD, GL_NICEST))                            \
    X(pf18, GL_INVALID_ENUM, NULL, 0, glHint(GL_FOG_HINT, BAD))                          \
    X(pf19, GL_INVALID_VALUE, NULL, 0, glClear(0x80000000u))                             \
    X(pf20, GL_INVALID_ENUM, NULL, 0, glPixelStorei(BAD, 4))                             \
    X(pf21, GL_INVALID_VALUE, NULL, 0, glPixelStorei(GL_PACK_ALIGNMENT, 3))              \
    X(pf22, GL_INVALID_VALUE, NULL, 0, glPixelStorei(GL_UNPACK_ALIGNMENT, 0))            \
    X(pf23, GL_INVALID_VALUE, NULL, 0, glViewport(0, 0, -1, 4))                          \
    X(pf24, GL_INVALID_VALUE, NULL, 0, glViewport(0, 0, 4, -1))                          \
    X(pf25, GL_INVALID_VALUE, NULL, 0, glScissor(0, 0, -1, 4))                           \
    X(pf26, GL_INVALID_VALUE, NULL, 0, glScissor(0, 0, 4, -1))                           \
    X(pf27, GL_INVALID_VALUE, NULL, 0, glLineWidth(0))                                   \
    X(pf28, GL_INVALID_VALUE, NULL, 0, glLineWidth(-1))                                  \
    X(pf29, GL_INVALID_VALUE, NULL, 0, glLineWidthx(0))                                  \
    X(pf30, GL_INVALID_VALUE, NULL, 0, glPointSize(0))                                   \
    X(pf31, GL_INVALID_VALUE, NULL, 0, glPointSize(-1))                                  \
    X(pf32, GL_INVALID_VALUE, NULL, 0, glPointSizex(-65536))                             \
    /* --- point parameters --- */                                                      \
    X(pp1, GL_INVALID_ENUM, NULL, 0, glPointParameterf(BAD, 1))                          \
    X(pp2, GL_INVALID_ENUM, NULL, 0, glPointParameterx(BAD, 1))                          \
    X(pp3, GL_INVALID_ENUM, NULL, 0, glPointParameterfv(BAD, fbuf))                      \
    X(pp4, GL_INVALID_ENUM, NULL, 0, glPointParameterxv(BAD, xbuf))                      \
    X(pp5, GL_INVALID_VALUE, NULL, 0, glPointParameterf(GL_POINT_SIZE_MIN, -1))          \
    X(pp6, GL_INVALID_VALUE, NULL, 0, glPointParameterf(GL_POINT_SIZE_MAX, -1))          \
    X(pp7, GL_INVALID_VALUE, NULL, 0, glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -1)) \
    X(pp8, GL_INVALID_VALUE, NULL, 0, glPointParameterx(GL_POINT_SIZE_MIN, -65536))      \
    /* Mesa accepts the vector-only POINT_DISTANCE_ATTENUATION through the scalar form. */ \
    X(pp9, GL_INVALID_ENUM, NULL, 1, glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 1)) \
    /* --- matrices --- */                                                              \
    X(mx1, GL_INVALID_ENUM, NULL, 0, glMatrixMode(BAD))                                  \
    X(mx2, GL_STACK_UNDERFLOW, NULL, 0, glPopMatrix())                                   \
    X(mx3, GL_STACK_UNDERFLOW, NULL, 0, glMatrixMode(GL_PROJECTION); SNAP; glPopMatrix()) \
    X(mx4, GL_STACK_UNDERFLOW, NULL, 0, glMatrixMode(GL_TEXTURE); SNAP; glPopMatrix())   \
    X(mx5, GL_STACK_OVERFLOW, NULL, 0, int n_ = geti(GL_MAX_MODELVIEW_STACK_DEPTH);      \
      while (--n_ > 0) glPushMatrix(); SNAP; glPushMatrix())                             \
    X(mx6, GL_STACK_OVERFLOW, NULL, 0, int n_ = geti(GL_MAX_PROJECTION_STACK_DEPTH);     \
      glMatrixMode(GL_PROJECTION); while (--n_ > 0) glPushMatrix(); SNAP; glPushMatrix()) \
    X(mx7, GL_STACK_OVERFLOW, NULL, 0, int n_ = geti(GL_MAX_TEXTURE_STACK_DEPTH);        \
      glMatrixMode(GL_TEXTURE); while (--n_ > 0) glPushMatrix(); SNAP; glPushMatrix())    \
    X(mx8, GL_STACK_UNDERFLOW, NULL, 0, glActiveTexture(GL_TEXTURE1);                    \
      glMatrixMode(GL_TEXTURE); SNAP; glPopMatrix())                                     \
    X(mx9, GL_INVALID_VALUE, NULL, 0, glFrustumf(-1, 1, -1, 1, 0, 10))                   \
    X(mx10, GL_INVALID_VALUE, NULL, 0, glFrustumf(-1, 1, -1, 1, 1, 0))                   \
    X(mx11, GL_INVALID_VALUE, NULL, 0, glFrustumf(-1, 1, -1, 1, -1, 10))                 \
    X(mx12, GL_INVALID_VALUE, NULL, 0, glFrustumf(1, 1, -1, 1, 1, 10))                   \
    X(mx13, GL_INVALID_VALUE, NULL, 0, glFrustumf(-1, 1, 1, 1, 1, 10))                   \
    X(mx14, GL_INVALID_VALUE, NULL, 0, glFrustumf(-1, 1, -1, 1, 2, 2))                   \
    X(mx15, GL_INVALID_VALUE, NULL, 0, glFrustumx(-65536, 65536, -65536, 65536, 0, 65536)) \
    X(mx16, GL_INVALID_VALUE, NULL, 0, glOrthof(1, 1, -1, 1, -1, 1))                     \
    X(mx17, GL_INVALID_VALUE, NULL, 0, glOrthof(-1, 1, 2, 2, -1, 1))                     \
    X(mx18, GL_INVALID_VALUE, NULL, 0, glOrthof(-1, 1, -1, 1, 3, 3))                     \
    X(mx19, GL_INVALID_VALUE, NULL, 0, glOrthox(65536, 65536, -65536, 65536, 0, 65536))  \
    /* --- clip planes --- */                                                           \
    X(cp1, GL_INVALID_ENUM, NULL, 0, glClipPlanef(GL_CLIP_PLANE0 + geti(GL_MAX_CLIP_PLANES), fbuf)) \
    X(cp2, GL_INVALID_ENUM, NULL, 0, glClipPlanex(BAD, xbuf))                            \
    X(cp3, GL_INVALID_ENUM, NULL, 0, glGetClipPlanef(BAD, fbuf))                         \
    X(cp4, GL_INVALID_ENUM, NULL, 0, glGetClipPlanex(GL_CLIP_PLANE0 + geti(GL_MAX_CLIP_PLANES), xbuf)) \
    /* --- fog --- */                                                                   \
    X(fg1, GL_INVALID_ENUM, NULL, 0, glFogf(BAD, 1))                                     \
    X(fg2, GL_INVALID_ENUM, NULL, 0, glFogf(GL_FOG_MODE, (GLfloat)BAD))                  \
    X(fg3, GL_INVALID_VALUE, NULL, 0, glFogf(GL_FOG_DENSITY, -1))                        \
    X(fg4, GL_INVALID_ENUM, NULL, 0, glFogx(BAD, 1))                                     \
    X(fg5, GL_INVALID_ENUM, NULL, 0, glFogx(GL_FOG_MODE, BAD))                           \
    X(fg6, GL_INVALID_VALUE, NULL, 0, glFogx(GL_FOG_DENSITY, -65536))                    \
    X(fg7, GL_INVALID_ENUM, NULL, 0, glFogfv(BAD, fbuf))                                 \
    X(fg8, GL_INVALID_VALUE, NULL, 0, fbuf[0] = -2; glFogfv(GL_FOG_DENSITY, fbuf); fbuf[0] = 0) \
    X(fg9, GL_INVALID_ENUM, NULL, 0, glFogxv(BAD, xbuf))                                 \
    /* Mesa accepts vector-only pnames through the scalar forms (it reads one value). */ \
    X(fg10, GL_INVALID_ENUM, NULL, 1, glFogf(GL_FOG_COLOR, 1))                           \
    /* --- lighting --- */                                                              \
    X(li1, GL_INVALID_ENUM, NULL, 0, glLightf(GL_LIGHT0 + geti(GL_MAX_LIGHTS), GL_SPOT_EXPONENT, 1)) \
    X(li2, GL_INVALID_ENUM, NULL, 0, glLightf(GL_LIGHT0, BAD, 1))                        \
    X(li3, GL_INVALID_ENUM, NULL, 1, glLightf(GL_LIGHT0, GL_AMBIENT, 1))                 \
    X(li4, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129))        \
    X(li5, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, -1))         \
    X(li6, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 91))           \
    X(li7, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, -1))           \
    X(li8, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, -1))  \
    X(li9, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -1))    \
    X(li10, GL_INVALID_VALUE, NULL, 0, glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, -1)) \
    X(li11, GL_INVALID_ENUM, NULL, 0, glLightx(BAD, GL_SPOT_EXPONENT, 1))                \
    X(li12, GL_INVALID_VALUE, NULL, 0, glLightx(GL_LIGHT0, GL_SPOT_CUTOFF, 100 << 16))   \
    X(li13, GL_INVALID_ENUM, NULL, 0, glLightfv(GL_LIGHT0, BAD, fbuf))                   \
    X(li14, GL_INVALID_ENUM, NULL, 0, glLightfv(BAD, GL_AMBIENT, fbuf))                  \
    X(li15, GL_INVALID_VALUE, NULL, 0, fbuf[0] = 200; glLightfv(GL_LIGHT0, GL_SPOT_EXPONENT, fbuf); \
      fbuf[0] = 0)                                                                       \
    X(li16, GL_INVALID_ENUM, NULL, 0, glLightxv(GL_LIGHT0, BAD, xbuf))                   \
    X(li17, GL_INVALID_ENUM, NULL, 0, glGetLightfv(GL_LIGHT0, BAD, fbuf))                \
    X(li18, GL_INVALID_ENUM, NULL, 0, glGetLightfv(BAD, GL_AMBIENT, fbuf))               \
    X(li19, GL_INVALID_ENUM, NULL, 0, glGetLightxv(GL_LIGHT0, BAD, xbuf))                \
    X(li20, GL_INVALID_ENUM, NULL, 0, glLightModelf(BAD, 1))                             \
    X(li21, GL_INVALID_ENUM, NULL, 1, glLightModelf(GL_LIGHT_MODEL_AMBIENT, 1))          \
    X(li22, GL_INVALID_ENUM, NULL, 0, glLightModelx(BAD, 1))                             \
    X(li23, GL_INVALID_ENUM, NULL, 0, glLightModelfv(BAD, fbuf))                         \
    X(li24, GL_INVALID_ENUM, NULL, 0, glLightModelxv(BAD, xbuf))                         \
    /* Mesa accepts GL_FRONT and GL_BACK (desktop GL's faces). */                       \
    X(ma1, GL_INVALID_ENUM, NULL, 1, glMaterialf(GL_FRONT, GL_SHININESS, 1))             \
    X(ma2, GL_INVALID_ENUM, NULL, 0, glMaterialf(GL_FRONT_AND_BACK, BAD, 1))             \
    X(ma3, GL_INVALID_ENUM, NULL, 1, glMaterialf(GL_FRONT_AND_BACK, GL_AMBIENT, 1))      \
    X(ma4, GL_INVALID_VALUE, NULL, 0, glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 129)) \
    X(ma5, GL_INVALID_VALUE, NULL, 0, glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, -1))  \
    X(ma6, GL_INVALID_ENUM, NULL, 0, glMaterialx(GL_FRONT_AND_BACK, BAD, 1))             \
    X(ma7, GL_INVALID_VALUE, NULL, 0, glMaterialx(GL_FRONT_AND_BACK, GL_SHININESS, 130 << 16)) \
    X(ma8, GL_INVALID_ENUM, NULL, 0, glMaterialfv(GL_FRONT_AND_BACK, BAD, fbuf))         \
    X(ma9, GL_INVALID_ENUM, NULL, 0, glMaterialxv(GL_FRONT_AND_BACK, BAD, xbuf))         \
    X(ma10, GL_INVALID_ENUM, NULL, 0, glGetMaterialfv(GL_FRONT, BAD, fbuf))              \
    X(ma11, GL_INVALID_ENUM, NULL, 0, glGetMaterialxv(GL_FRONT, BAD, xbuf))              \
    X(ma12, GL_INVALID_ENUM, NULL, 0, glGetMaterialfv(BAD, GL_AMBIENT, fbuf))            \
    /* --- queries --- */                                                               \
    X(q1, GL_INVALID_ENUM, NULL, 0, glGetBooleanv(BAD, bbuf))                            \
    X(q2, GL_INVALID_ENUM, NULL, 0, glGetIntegerv(BAD, ibuf))                            \
    X(q3, GL_INVALID_ENUM, NULL, 0, glGetFloatv(BAD, fbuf))                              \
    X(q4, GL_INVALID_ENUM, NULL, 0, glGetFixedv(BAD, xbuf))                              \
    X(q5, GL_INVALID_ENUM, NULL, 0, glGetString(BAD))                                    \
    X(q6, GL_INVALID_ENUM, NULL, 0, glGetPointerv(BAD, pbuf))                            \
    X(q7, GL_INVALID_ENUM, NULL, 0, glGetIntegerv(GL_TEXTURE_MIN_FILTER, ibuf))          \
    /* --- texture environment --- */                                                   \
    X(te1, GL_INVALID_ENUM, NULL, 0, glTexEnvf(BAD, GL_TEXTURE_ENV_MODE, GL_REPLACE))    \
    X(te2, GL_INVALID_ENUM, NULL, 0, glTexEnvf(GL_TEXTURE_ENV, BAD, GL_REPLACE))         \
    X(te3, GL_INVALID_ENUM, NULL, 0, glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLfloat)BAD)) \
    X(te4, GL_INVALID_ENUM, NULL, 0, glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, BAD))     \
    X(te5, GL_INVALID_ENUM, NULL, 0, glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB)) \
    X(te6, GL_INVALID_ENUM, NULL, 0, glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, BAD))        \
    X(te7, GL_INVALID_ENUM, NULL, 0, glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_ALPHA, BAD))      \
    X(te8, GL_INVALID_ENUM, NULL, 0, glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, BAD))    \
    X(te9, GL_INVALID_ENUM, NULL, 0, glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR)) \
    X(te10, GL_INVALID_VALUE, NULL, 0, glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3))       \
    X(te11, GL_INVALID_VALUE, NULL, 0, glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0.5f))  \
    X(te12, GL_INVALID_ENUM, NULL, 0, glTexEnvx(GL_TEXTURE_ENV, BAD, 0))                 \
    X(te13, GL_INVALID_ENUM, NULL, 0, glTexEnvfv(GL_TEXTURE_ENV, BAD, fbuf))             \
    X(te14, GL_INVALID_ENUM, NULL, 0, glTexEnviv(BAD, GL_TEXTURE_ENV_COLOR, ibuf))       \
    X(te15, GL_INVALID_ENUM, NULL, 0, glTexEnvxv(GL_TEXTURE_ENV, BAD, xbuf))             \
    X(te16, GL_INVALID_ENUM, NULL, 0, glGetTexEnvfv(BAD, GL_TEXTURE_ENV_MODE, fbuf))     \
    X(te17, GL_INVALID_ENUM, NULL, 0, glGetTexEnviv(GL_TEXTURE_ENV, BAD, ibuf))          \
    X(te18, GL_INVALID_ENUM, NULL, 0, glGetTexEnvxv(GL_TEXTURE_ENV, BAD, xbuf))          \
    X(te19, GL_INVALID_ENUM, NULL, 1, glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 1)) \
    X(te20, GL_INVALID_ENUM, PS, 0, glTexEnvi(GL_POINT_SPRITE_OES, BAD, GL_TRUE))        \
    /* --- texture parameters --- */                                                    \
    X(tp1, GL_INVALID_ENUM, NULL, 0, glTexParameterf(BAD, GL_TEXTURE_MIN_FILTER, GL_NEAREST)) \
    X(tp2, GL_INVALID_ENUM, NULL, 0, glTexParameterf(GL_TEXTURE_2D, BAD, GL_NEAREST))    \
    X(tp3, GL_INVALID_ENUM, NULL, 0, glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLfloat)BAD)) \
    X(tp4, GL_INVALID_ENUM, NULL, 0,                                                     \
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR))    \
    X(tp5, GL_INVALID_ENUM, NULL, 0, glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, 0x2900)) \
    X(tp6, GL_INVALID_ENUM, NULL, 0, glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, BAD)) \
    X(tp7, GL_INVALID_ENUM, NULL, 0, TEX; SNAP; glTexParameterx(GL_TEXTURE_2D, BAD, 0))  \
    X(tp8, GL_INVALID_ENUM, NULL, 0, glTexParameterfv(GL_TEXTURE_2D, BAD, fbuf))         \
    X(tp9, GL_INVALID_ENUM, NULL, 0, glTexParameteriv(BAD, GL_TEXTURE_WRAP_S, ibuf))     \
    X(tp10, GL_INVALID_ENUM, NULL, 0, glTexParameterxv(GL_TEXTURE_2D, BAD, xbuf))        \
    X(tp11, GL_INVALID_ENUM, NULL, 0, glGetTexParameterfv(BAD, GL_TEXTURE_WRAP_S, fbuf)) \
    X(tp12, GL_INVALID_ENUM, NULL, 0, glGetTexParameteriv(GL_TEXTURE_2D, BAD, ibuf))     \
    X(tp13, GL_INVALID_ENUM, NULL, 0, glGetTexParameterxv(GL_TEXTURE_2D, BAD, xbuf))     \
    /* --- texture objects and images --- */                                            \
    X(tx1, GL_INVALID_ENUM, NULL, 0, glBindTexture(BAD, 0))                              \
    X(tx2, GL_INVALID_VALUE, NULL, 0, glGenTextures(-1, (GLuint *)ibuf))                 \
    X(tx3, GL_INVALID_VALUE, NULL, 0, glDeleteTextures(-1, (GLuint *)ibuf))              \
    X(tx4, GL_INVALID_ENUM, NULL, 0,                                                     \
      glTexImage2D(BAD, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))           \
    X(tx5, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                         \
      glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, ubuf)) \
    X(tx6, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                         \
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, ubuf)) \
    X(tx7, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                         \
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))  \
    /* Any size fits (OES_texture_npot) up to the level's largest: MAX >> level. */      \
    X(tx8, GL_INVALID_VALUE, NULL, 1, TEX; SNAP;                                         \
      glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, geti(GL_MAX_TEXTURE_SIZE), 1, 0, GL_RGBA,  \
                   GL_UNSIGNED_BYTE, NULL))                                              \
    X(tx9, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                         \
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, geti(GL_MAX_TEXTURE_SIZE) * 2, 1, 0, GL_RGBA, \
                   GL_UNSIGNED_BYTE, NULL))                                              \
    X(tx10, GL_INVALID_OPERATION, NULL, 0, TEX; SNAP;                                    \
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))   \
    /* Mesa raises INVALID_VALUE for an unknown type. */                                 \
    X(tx11, GL_INVALID_ENUM, NULL, 1, TEX; SNAP;                                         \
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, BAD, ubuf))              \
    X(tx12, GL_INVALID_OPERATION, NULL, 0, TEX; SNAP;                                    \
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, ubuf)) \
    X(tx13, GL_INVALID_VALUE, NULL, 0, TEX_IMAGE; SNAP;                                  \
      glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))     \
    X(tx14, GL_INVALID_VALUE, NULL, 0, TEX_IMAGE; SNAP;                                  \
      glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))    \
    X(tx15, GL_INVALID_OPERATION, NULL, 0, TEX; SNAP;                                    \
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))     \
    X(tx16, GL_INVALID_ENUM, NULL, 0,                                                    \
      glTexSubImage2D(BAD, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))              \
    X(tx17, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 1))                        \
    X(tx18, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -4, 4, 0))                       \
    X(tx19, GL_INVALID_ENUM, NULL, 0, glCopyTexImage2D(BAD, 0, GL_RGBA, 0, 0, 4, 4, 0))  \
    X(tx20, GL_INVALID_OPERATION, NULL, 0, TEX; SNAP;                                    \
      glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1))                           \
    X(tx21, GL_INVALID_VALUE, NULL, 0, TEX_IMAGE; SNAP;                                  \
      glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 0, 0, 2, 2))                           \
    X(tx22, GL_INVALID_ENUM, NULL, 0, TEX; SNAP;                                         \
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, BAD, 4, 4, 0, 16, ubuf))                  \
    X(tx23, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGBA8_OES, 4, 4, 0, 3, ubuf)) \
    X(tx24, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glCompressedTexImage2D(GL_TEXTURE_2D, 1, GL_PALETTE4_RGBA8_OES, 4, 4, 0, 72, ubuf)) \
    /* Mesa raises INVALID_VALUE for a paletted CompressedTexSubImage2D. */              \
    X(tx25, GL_INVALID_OPERATION, NULL, 1, TEX; glCompressedTexImage2D(GL_TEXTURE_2D, 0, \
      GL_PALETTE4_RGBA8_OES, 4, 4, 0, 72, ubuf); SNAP;                                   \
      glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_PALETTE4_RGBA8_OES, 72, ubuf)) \
    X(tx26, GL_INVALID_ENUM, NULL, 0,                                                    \
      glCompressedTexSubImage2D(BAD, 0, 0, 0, 4, 4, GL_PALETTE4_RGBA8_OES, 72, ubuf))    \
    /* --- vertex arrays --- */                                                         \
    X(va1, GL_INVALID_VALUE, NULL, 0, glVertexPointer(1, GL_FLOAT, 0, ubuf))             \
    X(va2, GL_INVALID_VALUE, NULL, 0, glVertexPointer(5, GL_FLOAT, 0, ubuf))             \
    X(va3, GL_INVALID_ENUM, NULL, 0, glVertexPointer(3, GL_UNSIGNED_BYTE, 0, ubuf))      \
    /* Mesa raises INVALID_VALUE for a negative stride but changes array state. */       \
    X(va4, GL_INVALID_VALUE, NULL, 1, glVertexPointer(3, GL_FLOAT, -4, ubuf))            \
    X(va5, GL_INVALID_VALUE, NULL, 0, glColorPointer(3, GL_FLOAT, 0, ubuf))              \
    X(va6, GL_INVALID_ENUM, NULL, 0, glColorPointer(4, GL_SHORT, 0, ubuf))               \
    X(va7, GL_INVALID_VALUE, NULL, 1, glColorPointer(4, GL_FLOAT, -1, ubuf))             \
    X(va8, GL_INVALID_ENUM, NULL, 0, glNormalPointer(GL_UNSIGNED_BYTE, 0, ubuf))         \
    X(va9, GL_INVALID_VALUE, NULL, 1, glNormalPointer(GL_FLOAT, -1, ubuf))               \
    X(va10, GL_INVALID_VALUE, NULL, 0, glTexCoordPointer(1, GL_FLOAT, 0, ubuf))          \
    X(va11, GL_INVALID_ENUM, NULL, 0, glTexCoordPointer(2, GL_UNSIGNED_BYTE, 0, ubuf))   \
    X(va12, GL_INVALID_VALUE, NULL, 1, glTexCoordPointer(2, GL_FLOAT, -1, ubuf))         \
    X(va13, GL_INVALID_ENUM, PSA, 0, glPointSizePointerOES(GL_BYTE, 0, ubuf))            \
    X(va14, GL_INVALID_VALUE, PSA, 1, glPointSizePointerOES(GL_FLOAT, -1, ubuf))         \
    /* --- drawing --- */                                                               \
    X(dr1, GL_INVALID_ENUM, NULL, 0, glDrawArrays(BAD, 0, 3))                            \
    X(dr2, GL_INVALID_VALUE, NULL, 0, glDrawArrays(GL_TRIANGLES, 0, -1))                 \
    X(dr3, GL_INVALID_ENUM, NULL, 0, glDrawElements(BAD, 3, GL_UNSIGNED_BYTE, ubuf))     \
    X(dr4, GL_INVALID_ENUM, NULL, 0, glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, ubuf))    \
    X(dr5, GL_INVALID_VALUE, NULL, 0, glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_BYTE, ubuf)) \
    X(dr6, GL_INVALID_ENUM, NULL, 0, glEnableClientState(GL_VERTEX_ARRAY);               \
      glVertexPointer(2, GL_FLOAT, 0, fbuf); SNAP; glDrawArrays(GL_QUADS_BAD, 0, 3))      \
    /* --- buffer objects --- */                                                        \
    X(bo1, GL_INVALID_ENUM, NULL, 0, glBindBuffer(BAD, 0))                               \
    X(bo2, GL_INVALID_VALUE, NULL, 0, glGenBuffers(-1, (GLuint *)ibuf))                  \
    X(bo3, GL_INVALID_VALUE, NULL, 0, glDeleteBuffers(-1, (GLuint *)ibuf))               \
    X(bo4, GL_INVALID_ENUM, NULL, 0, BUF; SNAP; glBufferData(BAD, 4, ubuf, GL_STATIC_DRAW)) \
    X(bo5, GL_INVALID_ENUM, NULL, 0, BUF; SNAP; glBufferData(GL_ARRAY_BUFFER, 4, ubuf, BAD)) \
    X(bo6, GL_INVALID_VALUE, NULL, 0, BUF; SNAP;                                         \
      glBufferData(GL_ARRAY_BUFFER, -1, ubuf, GL_STATIC_DRAW))                           \
    X(bo7, GL_INVALID_OPERATION, NULL, 0, glBufferData(GL_ARRAY_BUFFER, 4, ubuf, GL_STATIC_DRAW)) \
    X(bo8, GL_INVALID_ENUM, NULL, 0, BUF; SNAP; glBufferSubData(BAD, 0, 4, ubuf))        \
    X(bo9, GL_INVALID_VALUE, NULL, 0, BUF; SNAP; glBufferSubData(GL_ARRAY_BUFFER, 8, 12, ubuf)) \
    X(bo10, GL_INVALID_VALUE, NULL, 0, BUF; SNAP; glBufferSubData(GL_ARRAY_BUFFER, -1, 4, ubuf)) \
    X(bo11, GL_INVALID_VALUE, NULL, 0, BUF; SNAP; glBufferSubData(GL_ARRAY_BUFFER, 0, -1, ubuf)) \
    X(bo12, GL_INVALID_OPERATION, NULL, 0, glBufferSubData(GL_ARRAY_BUFFER, 0, 4, ubuf)) \
    X(bo13, GL_INVALID_ENUM, NULL, 0, BUF; SNAP; glGetBufferParameteriv(BAD, GL_BUFFER_SIZE, ibuf)) \
    X(bo14, GL_INVALID_ENUM, NULL, 0, BUF; SNAP;                                         \
      glGetBufferParameteriv(GL_ARRAY_BUFFER, BAD, ibuf))                                \
    /* --- pixels --- */                                                                \
    X(rp1, GL_INVALID_VALUE, NULL, 0, glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf)) \
    X(rp2, GL_INVALID_VALUE, NULL, 0, glReadPixels(0, 0, 1, -1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf)) \
    /* Mesa raises INVALID_VALUE / INVALID_OPERATION for unknown format / type enums. */ \
    X(rp3, GL_INVALID_ENUM, NULL, 1, glReadPixels(0, 0, 1, 1, BAD, GL_UNSIGNED_BYTE, ubuf)) \
    X(rp4, GL_INVALID_ENUM, NULL, 1, glReadPixels(0, 0, 1, 1, GL_RGBA, BAD, ubuf))       \
    X(rp5, GL_INVALID_OPERATION, NULL, 0,                                                \
      glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, ubuf))                  \
    /* --- vector forms and more limits --- */                                          \
    X(vf1, GL_INVALID_VALUE, NULL, 0, xbuf[0] = 95 << 16;                                \
      glLightxv(GL_LIGHT0, GL_SPOT_CUTOFF, xbuf); xbuf[0] = 0)                           \
    X(vf2, GL_INVALID_VALUE, NULL, 0, xbuf[0] = -65536;                                  \
      glMaterialxv(GL_FRONT_AND_BACK, GL_SHININESS, xbuf); xbuf[0] = 0)                  \
    X(vf3, GL_INVALID_VALUE, NULL, 0, fbuf[0] = -1;                                      \
      glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, fbuf); fbuf[0] = 0)                  \
    X(vf4, GL_INVALID_VALUE, NULL, 0, xbuf[0] = 3 << 16;                                 \
      glTexEnvxv(GL_TEXTURE_ENV, GL_RGB_SCALE, xbuf); xbuf[0] = 0)                       \
    X(vf5, GL_INVALID_ENUM, NULL, 0, ibuf[0] = BAD;                                      \
      glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, ibuf); ibuf[0] = 0)                \
    X(vf6, GL_INVALID_ENUM, NULL, 0, ibuf[0] = BAD;                                      \
      glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, ibuf); ibuf[0] = 0)         \
    X(vf7, GL_INVALID_ENUM, NULL, 0, xbuf[0] = BAD;                                      \
      glFogxv(GL_FOG_MODE, xbuf); xbuf[0] = 0)                                           \
    X(vf8, GL_INVALID_ENUM, NULL, 0, fbuf[0] = (GLfloat)BAD;                             \
      glFogfv(GL_FOG_MODE, fbuf); fbuf[0] = 0)                                           \
    X(vf9, GL_INVALID_VALUE, NULL, 0, fbuf[0] = -1;                                      \
      glPointParameterfv(GL_POINT_SIZE_MIN, fbuf); fbuf[0] = 0)                          \
    X(vf10, GL_INVALID_VALUE, NULL, 0, xbuf[0] = -65536;                                 \
      glPointParameterxv(GL_POINT_FADE_THRESHOLD_SIZE, xbuf); xbuf[0] = 0)               \
    X(vf11, GL_INVALID_ENUM, NULL, 0, glGetLightxv(GL_LIGHT0 + geti(GL_MAX_LIGHTS), GL_AMBIENT, xbuf)) \
    X(vf12, GL_INVALID_ENUM, NULL, 0, glLightModelxv(0x0B51 /* LOCAL_VIEWER */, xbuf))  \
    X(vf13, GL_INVALID_ENUM, NULL, 0, glHint(GL_GENERATE_MIPMAP_HINT, BAD))              \
    X(vf14, GL_INVALID_VALUE, NULL, 0, glPixelStorei(GL_PACK_ALIGNMENT, 16))             \
    X(vf15, GL_INVALID_VALUE, NULL, 0, glLineWidthx(-65536))                             \
    X(vf16, GL_INVALID_VALUE, NULL, 0, glPointSizex(0))                                  \
    X(vf17, GL_INVALID_VALUE, NULL, 0, glFrustumx(-65536, 65536, -65536, 65536, 65536, 65536)) \
    X(vf18, GL_INVALID_VALUE, NULL, 0, glOrthox(-65536, 65536, 65536, 65536, 0, 65536))  \
    X(vf19, GL_INVALID_ENUM, PS, 0, glGetTexEnviv(GL_POINT_SPRITE_OES, BAD, ibuf))       \
    X(vf20, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glTexImage2D(GL_TEXTURE_2D, 20, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))  \
    X(vf21, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_RGBA8_OES, 4, 4, 1, 1040, ubuf)) \
    X(vf22, GL_INVALID_VALUE, NULL, 0, TEX; SNAP;                                        \
      glCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 0, 0, 4, 4, 0))                       \
    X(vf23, GL_INVALID_VALUE, NULL, 0, TEX_IMAGE; SNAP;                                  \
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ubuf))    \
    X(vf24, GL_INVALID_ENUM, NULL, 0, glDrawElements(GL_TRIANGLES, 3, GL_SHORT, ubuf))   \
    X(vf25, GL_INVALID_ENUM, NULL, 0, glDisable(GL_LIGHT0 + geti(GL_MAX_LIGHTS)))        \
    X(vf26, GL_INVALID_ENUM, NULL, 0, glIsEnabled(GL_CLIP_PLANE0 + geti(GL_MAX_CLIP_PLANES))) \
    X(vf27, GL_INVALID_ENUM, NULL, 0, glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, ibuf)) \
    /* --- OES_matrix_palette --- */                                                    \
    X(mp1, GL_INVALID_VALUE, MP, 0, pCurrentPaletteMatrix((GLuint)geti(GL_MAX_PALETTE_MATRICES_OES))) \
    X(mp2, GL_INVALID_VALUE, MP, 0,                                                      \
      pMatrixIndexPointer(geti(GL_MAX_VERTEX_UNITS_OES) + 1, GL_UNSIGNED_BYTE, 0, ubuf))  \
    X(mp3, GL_INVALID_ENUM, MP, 0, pMatrixIndexPointer(2, GL_FLOAT, 0, ubuf))            \
    X(mp4, GL_INVALID_VALUE, MP, 0, pMatrixIndexPointer(2, GL_UNSIGNED_BYTE, -1, ubuf))   \
    X(mp5, GL_INVALID_VALUE, MP, 0, pWeightPointer(geti(GL_MAX_VERTEX_UNITS_OES) + 1, GL_FLOAT, 0, ubuf)) \
    X(mp6, GL_INVALID_ENUM, MP, 0, pWeightPointer(2, GL_UNSIGNED_BYTE, 0, ubuf))         \
    X(mp7, GL_INVALID_VALUE, MP, 0, pWeightPointer(2, GL_FLOAT, -1, ubuf))               \
    /* --- OES_blend_subtract, _func_separate, _equation_separate --- */                \
    X(bl1, GL_INVALID_ENUM, "GL_OES_blend_subtract", 0, pBlendEquation(BAD))             \
    X(bl2, GL_INVALID_ENUM, "GL_OES_blend_func_separate", 0,                             \
      pBlendFuncSeparate(BAD, GL_ONE, GL_ONE, GL_ONE))                                   \
    X(bl3, GL_INVALID_ENUM, "GL_OES_blend_func_separate", 0,                             \
      pBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, BAD))                                   \
    X(bl4, GL_INVALID_ENUM, "GL_OES_blend_equation_separate", 0,                         \
      pBlendEquationSeparate(GL_FUNC_ADD_OES, BAD))                                      \
    /* --- OES_mapbuffer --- */                                                         \
    X(mb1, GL_INVALID_ENUM, MB, 0, BUF; SNAP; pMapBuffer(GL_ARRAY_BUFFER, BAD))          \
    X(mb2, GL_INVALID_OPERATION, MB, 0, pMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES))  \
    X(mb3, GL_INVALID_OPERATION, MB, 0, BUF; SNAP; pUnmapBuffer(GL_ARRAY_BUFFER))        \
    X(mb4, GL_INVALID_ENUM, MB, 0, BUF; SNAP; pGetBufferPointerv(GL_ARRAY_BUFFER, BAD, pbuf)) \
    X(mb5, GL_INVALID_ENUM, MB, 0, BUF; SNAP; pMapBuffer(BAD, GL_WRITE_ONLY_OES))

#define GL_QUADS_BAD 0x0007 /* desktop GL_QUADS: not a mode in ES */

#define DEF(id, err, ext, strict, ...)                                                   \
    static void row_##id(void)                                                           \
    {                                                                                    \
        __VA_ARGS__;                                                                     \
    }
ERRORS(DEF)

struct row {
    const char *call;
    void (*run)(void);
    GLenum expected;
    const char *ext;
    int strict;
};

#define ROW(id, err, ext, strict, ...) {#__VA_ARGS__, row_##id, err, ext, strict},
static const struct row rows[] = {ERRORS(ROW)};

/* ---------------------------------------------------------------------------------- */

static const char *extensions;

static int has_ext(const char *name)
{
    const char *p = extensions;
    size_t n = strlen(name);
    while (p && (p = strstr(p, name)) != NULL) {
        if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
        p += n;
    }
    return 0;
}

static const GLenum snap_pnames[] = {
    GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_CURRENT_TEXTURE_COORDS, GL_CLIENT_ACTIVE_TEXTURE,
    GL_ACTIVE_TEXTURE, GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_STRIDE,
    GL_VERTEX_ARRAY_TYPE, GL_NORMAL_ARRAY, GL_NORMAL_ARRAY_STRIDE, GL_NORMAL_ARRAY_TYPE,
    GL_COLOR_ARRAY, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_STRIDE, GL_COLOR_ARRAY_TYPE,
    GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_STRIDE,
    GL_TEXTURE_COORD_ARRAY_TYPE, GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING,
    GL_VERTEX_ARRAY_BUFFER_BINDING, GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX,
    GL_TEXTURE_MATRIX, GL_VIEWPORT, GL_DEPTH_RANGE, GL_MODELVIEW_STACK_DEPTH,
    GL_PROJECTION_STACK_DEPTH, GL_TEXTURE_STACK_DEPTH, GL_MATRIX_MODE, GL_NORMALIZE,
    GL_RESCALE_NORMAL, GL_FOG_COLOR, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_MODE,
    GL_FOG, GL_SHADE_MODEL, GL_LIGHTING, GL_COLOR_MATERIAL, GL_LIGHT_MODEL_AMBIENT,
    GL_LIGHT_MODEL_TWO_SIDE, GL_POINT_SIZE, GL_POINT_SMOOTH, GL_POINT_SIZE_MIN,
    GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE, GL_POINT_DISTANCE_ATTENUATION,
    GL_LINE_WIDTH, GL_LINE_SMOOTH, GL_CULL_FACE, GL_CULL_FACE_MODE, GL_FRONT_FACE,
    GL_POLYGON_OFFSET_FACTOR, GL_POLYGON_OFFSET_UNITS, GL_POLYGON_OFFSET_FILL, GL_MULTISAMPLE,
    GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE,
    GL_SAMPLE_COVERAGE_VALUE, GL_SAMPLE_COVERAGE_INVERT, GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D,
    GL_SCISSOR_TEST, GL_SCISSOR_BOX, GL_ALPHA_TEST, GL_ALPHA_TEST_FUNC, GL_ALPHA_TEST_REF,
    GL_STENCIL_TEST, GL_STENCIL_FUNC, GL_STENCIL_VALUE_MASK, GL_STENCIL_REF, GL_STENCIL_FAIL,
    GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_DEPTH_TEST, GL_DEPTH_FUNC,
    GL_BLEND, GL_BLEND_SRC, GL_BLEND_DST, GL_DITHER, GL_COLOR_LOGIC_OP, GL_LOGIC_OP_MODE,
    GL_COLOR_WRITEMASK, GL_DEPTH_WRITEMASK, GL_STENCIL_WRITEMASK, GL_COLOR_CLEAR_VALUE,
    GL_DEPTH_CLEAR_VALUE, GL_STENCIL_CLEAR_VALUE, GL_UNPACK_ALIGNMENT, GL_PACK_ALIGNMENT,
    GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT, GL_FOG_HINT,
    GL_GENERATE_MIPMAP_HINT, GL_CLIP_PLANE0, GL_LIGHT0,
};

static const GLenum ext_pnames[][2] = {
    {GL_POINT_SIZE_ARRAY_TYPE_OES, 0}, {GL_POINT_SIZE_ARRAY_STRIDE_OES, 0},
    {GL_POINT_SPRITE_OES, 1}, {GL_CURRENT_PALETTE_MATRIX_OES, 2},
    {GL_MATRIX_INDEX_ARRAY_SIZE_OES, 2}, {GL_MATRIX_INDEX_ARRAY_TYPE_OES, 2},
    {GL_MATRIX_INDEX_ARRAY_STRIDE_OES, 2}, {GL_WEIGHT_ARRAY_SIZE_OES, 2},
    {GL_WEIGHT_ARRAY_TYPE_OES, 2}, {GL_WEIGHT_ARRAY_STRIDE_OES, 2},
    {GL_BLEND_EQUATION_OES, 3}, {GL_BLEND_SRC_RGB_OES, 4}, {GL_BLEND_DST_ALPHA_OES, 4},
    {GL_BLEND_EQUATION_ALPHA_OES, 5},
};
static const char *const ext_names[] = {
    PSA, PS, MP, "GL_OES_blend_subtract", "GL_OES_blend_func_separate",
    "GL_OES_blend_equation_separate",
};

static size_t put(unsigned char *out, size_t at, const void *p, size_t n)
{
    if (at + n <= sizeof snap_before)
        memcpy(out + at, p, n);
    return at + n;
}

/*
 * Everything a bad call must leave alone, serialized. Restores what it changes (the
 * active texture unit) and raises no error.
 */
static void snapshot(unsigned char *out)
{
    static const GLenum light_p[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION,
                                     GL_SPOT_DIRECTION, GL_SPOT_EXPONENT, GL_SPOT_CUTOFF,
                                     GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION,
                                     GL_QUADRATIC_ATTENUATION};
    static const GLenum mat_p[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION,
                                   GL_SHININESS};
    static const GLenum env_p[] = {GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB,
                                   GL_COMBINE_ALPHA, GL_SRC0_RGB, GL_SRC1_RGB, GL_SRC2_RGB,
                                   GL_SRC0_ALPHA, GL_SRC1_ALPHA, GL_SRC2_ALPHA,
                                   GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB,
                                   GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA,
                                   GL_RGB_SCALE, GL_ALPHA_SCALE};
    static const GLenum tex_p[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,
                                   GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_GENERATE_MIPMAP};
    static const GLenum ptr_p[] = {GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER,
                                   GL_COLOR_ARRAY_POINTER, GL_TEXTURE_COORD_ARRAY_POINTER};
    size_t at = 0, k;
    GLfloat f[16];
    GLint i[16];
    GLint active = geti(GL_ACTIVE_TEXTURE), units = geti(GL_MAX_TEXTURE_UNITS), u;
    GLint lights = geti(GL_MAX_LIGHTS), planes = geti(GL_MAX_CLIP_PLANES), l;

    memset(out, 0, sizeof snap_before);
    for (k = 0; k < sizeof snap_pnames / sizeof *snap_pnames; ++k) {
        memset(f, 0, sizeof f);
        memset(i, 0, sizeof i);
        glGetFloatv(snap_pnames[k], f);
        glGetIntegerv(snap_pnames[k], i);
        at = put(out, at, f, sizeof f);
        at = put(out, at, i, sizeof i);
    }
    for (k = 0; k < sizeof ext_pnames / sizeof *ext_pnames; ++k) {
        if (!has_ext(ext_names[ext_pnames[k][1]]))
            continue;
        memset(i, 0, sizeof i);
        glGetIntegerv(ext_pnames[k][0], i);
        at = put(out, at, i, sizeof i);
    }
    for (l = 0; l < lights; ++l)
        for (k = 0; k < sizeof light_p / sizeof *light_p; ++k) {
            memset(f, 0, sizeof f);
            glGetLightfv(GL_LIGHT0 + l, light_p[k], f);
            at = put(out, at, f, 4 * sizeof *f);
        }
    for (k = 0; k < sizeof mat_p / sizeof *mat_p; ++k) {
        memset(f, 0, sizeof f);
        glGetMaterialfv(GL_FRONT, mat_p[k], f);
        at = put(out, at, f, 4 * sizeof *f);
    }
    for (l = 0; l < planes; ++l) {
        glGetClipPlanef(GL_CLIP_PLANE0 + l, f);
        at = put(out, at, f, 4 * sizeof *f);
    }
    for (u = 0; u < units; ++u) {
        glActiveTexture(GL_TEXTURE0 + u);
        for (k = 0; k < sizeof env_p / sizeof *env_p; ++k) {
            memset(f, 0, sizeof f);
            glGetTexEnvfv(GL_TEXTURE_ENV, env_p[k], f);
            at = put(out, at, f, 4 * sizeof *f);
        }
        glGetIntegerv(GL_TEXTURE_MATRIX, i);
        at = put(out, at, i, sizeof i);
        glGetIntegerv(GL_TEXTURE_STACK_DEPTH, i);
        at = put(out, at, i, sizeof *i);
        glGetIntegerv(GL_TEXTURE_2D, i);
        at = put(out, at, i, sizeof *i);
    }
    glActiveTexture((GLenum)active);
    for (k = 0; k < sizeof tex_p / sizeof *tex_p; ++k) {
        glGetTexParameteriv(GL_TEXTURE_2D, tex_p[k], i);
        at = put(out, at, i, sizeof *i);
    }
    for (k = 0; k < sizeof ptr_p / sizeof *ptr_p; ++k) {
        void *p = NULL;
        glGetPointerv(ptr_p[k], &p);
        at = put(out, at, &p, sizeof p);
    }
    if (geti(GL_ARRAY_BUFFER_BINDING) != 0) {
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, i);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, i + 1);
        at = put(out, at, i, 2 * sizeof *i);
    }
    {
        GLubyte px[SW * SH * 4];
        GLint pack = geti(GL_PACK_ALIGNMENT);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, SW, SH, GL_RGBA, GL_UNSIGNED_BYTE, px);
        glPixelStorei(GL_PACK_ALIGNMENT, pack);
        at = put(out, at, px, sizeof px);
    }
    if (at > sizeof snap_before) {
        fprintf(stderr, "snapshot too large (%u bytes)\n", (unsigned)at);
        exit(2);
    }
}

static const char *error_name(GLenum e)
{
    switch (e) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "?";
    }
}

int main(void)
{
    static unsigned char after[sizeof snap_before];
    size_t r;
    int tested = 0, skipped = 0, strict;

    ct_init(SW, SH);
    extensions = (const char *)glGetString(GL_EXTENSIONS);
    strict = ct_strict();
    memset(ubuf, 0x40, sizeof ubuf);
    pBlendEquation = (PFNGLBLENDEQUATIONOESPROC)eglGetProcAddress("glBlendEquationOES");
    pBlendFuncSeparate = (PFNGLBLENDFUNCSEPARATEOESPROC)eglGetProcAddress("glBlendFuncSeparateOES");
    pBlendEquationSeparate = (PFNGLBLENDEQUATIONSEPARATEOESPROC)eglGetProcAddress("glBlendEquationSeparateOES");
    pCurrentPaletteMatrix = (PFNGLCURRENTPALETTEMATRIXOESPROC)eglGetProcAddress("glCurrentPaletteMatrixOES");
    pMatrixIndexPointer = (PFNGLMATRIXINDEXPOINTEROESPROC)eglGetProcAddress("glMatrixIndexPointerOES");
    pWeightPointer = (PFNGLWEIGHTPOINTEROESPROC)eglGetProcAddress("glWeightPointerOES");
    pMapBuffer = (PFNGLMAPBUFFEROESPROC)eglGetProcAddress("glMapBufferOES");
    pUnmapBuffer = (PFNGLUNMAPBUFFEROESPROC)eglGetProcAddress("glUnmapBufferOES");
    pGetBufferPointerv = (PFNGLGETBUFFERPOINTERVOESPROC)eglGetProcAddress("glGetBufferPointervOES");

    for (r = 0; r < sizeof rows / sizeof *rows; ++r) {
        const struct row *w = &rows[r];
        EGLContext c;
        GLenum got, next;
        int unchanged;

        if (w->ext && !has_ext(w->ext)) {
            ++skipped;
            continue;
        }
        /* A fresh context: each row starts from the initial state. */
        c = eglCreateContext(ct.display, ct.config, EGL_NO_CONTEXT, NULL);
        if (c == EGL_NO_CONTEXT || !eglMakeCurrent(ct.display, ct.surface, ct.surface, c)) {
            fprintf(stderr, "cannot make a context current for row %u\n", (unsigned)r);
            return 2;
        }
        glClearColor(0.25f, 0.5f, 0.75f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK_GL(GL_NO_ERROR);
        snapshot(snap_before);
        w->run();
        got = glGetError();
        next = glGetError();
        snapshot(after);
        unchanged = memcmp(snap_before, after, sizeof after) == 0;
        ++ct.checks;
        if (got != w->expected || next != GL_NO_ERROR || !unchanged) {
            char m[600];
            snprintf(m, sizeof m, "%s: raised %s then %s, expected %s%s", w->call,
                     error_name(got), error_name(next), error_name(w->expected),
                     unchanged ? "" : "; state changed");
            if (w->strict && !strict) {
                fprintf(stderr, "known deviation: %s\n", m);
                glGetError(); /* the snapshot may have tripped over the deviation */
            } else {
                ct_fail(__FILE__, __LINE__, m);
            }
        }
        CHECK_GL(GL_NO_ERROR);
        ++tested;
        eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context);
        eglDestroyContext(ct.display, c);
    }

    /* The first error sticks until glGetError reads it; later ones are dropped. */
    glEnable(BAD);
    glLineWidth(-1);
    glPopMatrix();
    CHECK_GL(GL_INVALID_ENUM);
    CHECK_GL(GL_NO_ERROR);
    glPopMatrix();
    glEnable(BAD);
    CHECK_GL(GL_STACK_UNDERFLOW);
    CHECK_GL(GL_NO_ERROR);

    {
        int rc = ct_done(); /* its summary line, then ours last for the harness log */
        printf("%d (entry point, error) pairs tested, %d skipped (extension not listed)\n", tested,
               skipped);
        return rc;
    }
}
