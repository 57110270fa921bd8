/*
 * Fog state: mode, density, start, end, color.
 *
 * Checks made only under ct_strict(), where Mesa departs from the specification: Mesa keeps
 * the fog color unclamped and accepts FOG_COLOR through the single-value commands.
 */
#include "common.h"

static GLint geti(GLenum pname)
{
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
}

static GLfloat getf(GLenum pname)
{
    GLfloat v = -12345.0f;
    glGetFloatv(pname, &v);
    return v;
}

static GLfixed getx(GLenum pname)
{
    GLfixed v = -12345;
    glGetFixedv(pname, &v);
    return v;
}

int main(void)
{
    GLfloat f[4];
    GLfixed x[4];
    GLint iv[4];
    GLboolean b[4];

    ct_init(16, 16);

    /* Defaults. */
    CHECK(geti(GL_FOG_MODE) == GL_EXP);
    CHECK(getf(GL_FOG_DENSITY) == 1.0f);
    CHECK(getf(GL_FOG_START) == 0.0f);
    CHECK(getf(GL_FOG_END) == 1.0f);
    glGetFloatv(GL_FOG_COLOR, f);
    CHECK(f[0] == 0 && f[1] == 0 && f[2] == 0 && f[3] == 0);
    CHECK(geti(GL_FOG_HINT) == GL_DONT_CARE);
    CHECK(!glIsEnabled(GL_FOG));
    CHECK_GL(GL_NO_ERROR);

    /* Mode: LINEAR, EXP, EXP2, through every entry point (fixed point passes the
     * enumerant unconverted). */
    glFogf(GL_FOG_MODE, (GLfloat)GL_LINEAR);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_FOG_MODE) == GL_LINEAR);
    CHECK(getf(GL_FOG_MODE) == (GLfloat)GL_LINEAR);
    glFogx(GL_FOG_MODE, GL_EXP2);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_FOG_MODE) == GL_EXP2);
    f[0] = (GLfloat)GL_EXP;
    glFogfv(GL_FOG_MODE, f);
    CHECK(geti(GL_FOG_MODE) == GL_EXP);
    x[0] = GL_LINEAR;
    glFogxv(GL_FOG_MODE, x);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_FOG_MODE) == GL_LINEAR);
    glFogf(GL_FOG_MODE, (GLfloat)GL_LESS);
    CHECK_GL(GL_INVALID_ENUM);
    glFogx(GL_FOG_MODE, GL_LINEAR << 16);
    CHECK_GL(GL_INVALID_ENUM);
    f[0] = (GLfloat)GL_FOG;
    glFogfv(GL_FOG_MODE, f);
    CHECK_GL(GL_INVALID_ENUM);
    x[0] = 0;
    glFogxv(GL_FOG_MODE, x);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_FOG_MODE) == GL_LINEAR);

    /* Density >= 0; start and end are any values. */
    glFogf(GL_FOG_DENSITY, 0.5f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_FOG_DENSITY) == 0.5f);
    CHECK(getx(GL_FOG_DENSITY) == 0x8000);
    glFogf(GL_FOG_DENSITY, -0.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glFogx(GL_FOG_DENSITY, -1);
    CHECK_GL(GL_INVALID_VALUE);
    f[0] = -2.0f;
    glFogfv(GL_FOG_DENSITY, f);
    CHECK_GL(GL_INVALID_VALUE);
    x[0] = -0x10000;
    glFogxv(GL_FOG_DENSITY, x);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(getf(GL_FOG_DENSITY) == 0.5f);
    glFogx(GL_FOG_DENSITY, 0x20000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_FOG_DENSITY) == 2.0f);
    glFogf(GL_FOG_DENSITY, 0.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_FOG_DENSITY) == 0.0f);

    glFogf(GL_FOG_START, -3.5f);
    glFogf(GL_FOG_END, 10.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_FOG_START) == -3.5f);
    CHECK(getf(GL_FOG_END) == 10.0f);
    CHECK(getx(GL_FOG_START) == -0x38000);
    CHECK(geti(GL_FOG_END) == 10);
    glFogx(GL_FOG_START, 0x18000);
    x[0] = 0x50000;
    glFogxv(GL_FOG_END, x);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_FOG_START) == 1.5f);
    CHECK(getf(GL_FOG_END) == 5.0f);
    f[0] = 7.0f;
    glFogfv(GL_FOG_START, f);
    CHECK(getf(GL_FOG_START) == 7.0f);

    /* Color: clamped to [0, 1]; normalized in integer queries. */
    f[0] = 0.25f;
    f[1] = 0.5f;
    f[2] = 0.75f;
    f[3] = 1.0f;
    glFogfv(GL_FOG_COLOR, f);
    CHECK_GL(GL_NO_ERROR);
    glGetFixedv(GL_FOG_COLOR, x);
    CHECK(x[0] == 0x4000 && x[1] == 0x8000 && x[2] == 0xc000 && x[3] == 0x10000);
    glGetIntegerv(GL_FOG_COLOR, iv);
    CHECK(iv[3] == 0x7fffffff);
    glGetBooleanv(GL_FOG_COLOR, b);
    CHECK(b[0] == GL_TRUE && b[3] == GL_TRUE);
    f[0] = 2.0f;
    f[1] = -1.0f;
    f[2] = 0.5f;
    f[3] = 0.0f;
    glFogfv(GL_FOG_COLOR, f);
    glGetFloatv(GL_FOG_COLOR, f);
    if (ct_strict())
        CHECK(f[0] == 1.0f && f[1] == 0.0f && f[2] == 0.5f && f[3] == 0.0f);
    x[0] = 0x8000;
    x[1] = 0x20000;
    x[2] = -0x10000;
    x[3] = 0x10000;
    glFogxv(GL_FOG_COLOR, x);
    CHECK_GL(GL_NO_ERROR);
    glGetFloatv(GL_FOG_COLOR, f);
    CHECK(f[0] == 0.5f && f[3] == 1.0f);
    if (ct_strict())
        CHECK(f[1] == 1.0f && f[2] == 0.0f);

    /* Unknown names. (FOG_COLOR through the single-value commands is a vector name.) */
    glFogf(GL_FOG_HINT, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glFogx(GL_FOG, 0);
    CHECK_GL(GL_INVALID_ENUM);
    glFogfv(GL_LIGHT_MODEL_AMBIENT, f);
    CHECK_GL(GL_INVALID_ENUM);
    glFogxv(GL_POINT_SIZE, x);
    CHECK_GL(GL_INVALID_ENUM);
    if (ct_strict()) {
        glFogf(GL_FOG_COLOR, 1.0f);
        CHECK_GL(GL_INVALID_ENUM);
        glFogx(GL_FOG_COLOR, 0x10000);
        CHECK_GL(GL_INVALID_ENUM);
        glGetFloatv(GL_FOG_COLOR, f);
        CHECK(f[0] == 0.5f && f[1] == 1.0f && f[2] == 0.0f && f[3] == 1.0f);
    }
    CHECK(geti(GL_FOG_MODE) == GL_LINEAR);

    glEnable(GL_FOG);
    glHint(GL_FOG_HINT, GL_NICEST);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsEnabled(GL_FOG));
    CHECK(geti(GL_FOG_HINT) == GL_NICEST);
    return ct_done();
}
