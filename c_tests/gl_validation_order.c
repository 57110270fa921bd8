/*
 * gl_validation_order.c: every vector setter validates its names before it reads its
 * pointer, so a bad name gives GL_INVALID_ENUM even when the pointer is NULL (conformance
 * suites call them so). With valid names, a NULL pointer is the application's error; this
 * library then reads and changes nothing.
 * ct:no-diff (Mesa's fixed-point entry points convert their values before validating the
 * names, and crash on these NULL pointers)
 */
#include "common.h"

/* Extension functions through eglGetProcAddress (Mesa exports them only that way). */
static PFNGLTEXGENFVOESPROC glTexGenfvOES;
static PFNGLTEXGENIVOESPROC glTexGenivOES;
static PFNGLTEXGENXVOESPROC glTexGenxvOES;

int main(void)
{
    GLfloat f[4] = {0};
    GLint i[4] = {0};

    ct_init(4, 4);
    glTexGenfvOES = (PFNGLTEXGENFVOESPROC)eglGetProcAddress("glTexGenfvOES");
    glTexGenivOES = (PFNGLTEXGENIVOESPROC)eglGetProcAddress("glTexGenivOES");
    glTexGenxvOES = (PFNGLTEXGENXVOESPROC)eglGetProcAddress("glTexGenxvOES");
    CHECK(glTexGenfvOES && glTexGenivOES && glTexGenxvOES);

    /* Bad names, NULL pointers: GL_INVALID_ENUM each. */
    glFogfv(0, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glFogxv(0, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glLightfv(GL_LIGHT0 + 8, GL_AMBIENT, NULL); /* GL_MAX_LIGHTS is 8 */
    CHECK_GL(GL_INVALID_ENUM);
    glLightfv(GL_LIGHT0, GL_TEXTURE_2D, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glLightxv(GL_LIGHT0 + 8, GL_POSITION, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glLightModelfv(GL_LIGHT0, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glLightModelxv(GL_LIGHT0, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialfv(GL_FRONT, GL_AMBIENT, NULL); /* ES 1.1: only GL_FRONT_AND_BACK */
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialxv(GL_FRONT_AND_BACK, GL_POSITION, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glPointParameterfv(GL_POINT_SIZE, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glPointParameterxv(0, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_2D, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvxv(GL_POINT_SPRITE_OES, GL_TEXTURE_ENV_MODE, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glClipPlanef(GL_CLIP_PLANE0 + 6, NULL); /* GL_MAX_CLIP_PLANES is 6 */
    CHECK_GL(GL_INVALID_ENUM);
    glClipPlanex(GL_LIGHT0, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glTexGenfvOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_2D, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glTexGenivOES(GL_TEXTURE_2D, GL_TEXTURE_GEN_MODE_OES, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glTexGenxvOES(0, 0, NULL);
    CHECK_GL(GL_INVALID_ENUM);

    /* Bad names with good pointers: the same errors, nothing set. */
    f[0] = 0.5f;
    glLightfv(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, f);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnviv(GL_TEXTURE_ENV, GL_FOG, i);
    CHECK_GL(GL_INVALID_ENUM);

    /* Good names, NULL pointers: nothing read, nothing changed, no error. */
    glFogfv(GL_FOG_COLOR, NULL);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, NULL);
    glLightModelxv(GL_LIGHT_MODEL_TWO_SIDE, NULL);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, NULL);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, NULL);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, NULL);
    glClipPlanef(GL_CLIP_PLANE2, NULL);
    glTexGenivOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, NULL);
    CHECK_GL(GL_NO_ERROR);
    glGetFloatv(GL_FOG_COLOR, f);
    CHECK(f[0] == 0 && f[1] == 0 && f[2] == 0 && f[3] == 0);
    glGetMaterialfv(GL_FRONT, GL_SHININESS, f);
    CHECK(f[0] == 0);

    /* Vector names through the scalar calls stay GL_INVALID_ENUM. */
    glFogf(GL_FOG_COLOR, 1);
    CHECK_GL(GL_INVALID_ENUM);
    glLightf(GL_LIGHT0, GL_POSITION, 1);
    CHECK_GL(GL_INVALID_ENUM);
    /* And valid calls still set their state. */
    f[0] = 0.25f;
    f[1] = 0.5f;
    f[2] = 0.75f;
    f[3] = 1;
    glFogfv(GL_FOG_COLOR, f);
    glGetFloatv(GL_FOG_COLOR, f);
    CHECK(f[0] == 0.25f && f[3] == 1);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
