/*
 * Lighting state: lights, light model, material, color material tracking.
 *
 * Checks made only under ct_strict(), where Mesa departs from the specification: Mesa accepts
 * vector parameter names through the single-value commands.
 */
#include "common.h"

static int eq4(const GLfloat *v, GLfloat a, GLfloat b, GLfloat c, GLfloat d)
{
    return v[0] == a && v[1] == b && v[2] == c && v[3] == d;
}

static int eq4x(const GLfixed *v, GLfixed a, GLfixed b, GLfixed c, GLfixed d)
{
    return v[0] == a && v[1] == b && v[2] == c && v[3] == d;
}

static GLfloat light1(GLenum light, GLenum pname)
{
    GLfloat v = -12345.0f;
    glGetLightfv(light, pname, &v);
    return v;
}

static GLfloat material1(GLenum face, GLenum pname)
{
    GLfloat v = -12345.0f;
    glGetMaterialfv(face, pname, &v);
    return v;
}

int main(void)
{
    GLint max_lights = 0, i;
    GLfloat f[4];
    GLfixed x[4];
    GLint iv[4];
    GLboolean b = 7;

    ct_init(16, 16);
    glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
    CHECK(max_lights >= 8);
    CHECK_GL(GL_NO_ERROR);

    /* Defaults. */
    for (i = 0; i < max_lights; ++i) {
        GLenum l = GL_LIGHT0 + (GLenum)i;
        GLfloat c = i == 0 ? 1.0f : 0.0f;
        glGetLightfv(l, GL_AMBIENT, f);
        CHECK(eq4(f, 0, 0, 0, 1));
        glGetLightfv(l, GL_DIFFUSE, f);
        CHECK(eq4(f, c, c, c, 1));
        glGetLightfv(l, GL_SPECULAR, f);
        CHECK(eq4(f, c, c, c, 1));
        glGetLightfv(l, GL_POSITION, f);
        CHECK(eq4(f, 0, 0, 1, 0));
        glGetLightfv(l, GL_SPOT_DIRECTION, f);
        CHECK(f[0] == 0 && f[1] == 0 && f[2] == -1);
        CHECK(light1(l, GL_SPOT_EXPONENT) == 0.0f);
        CHECK(light1(l, GL_SPOT_CUTOFF) == 180.0f);
        CHECK(light1(l, GL_CONSTANT_ATTENUATION) == 1.0f);
        CHECK(light1(l, GL_LINEAR_ATTENUATION) == 0.0f);
        CHECK(light1(l, GL_QUADRATIC_ATTENUATION) == 0.0f);
        CHECK(!glIsEnabled(l));
    }
    glGetLightxv(GL_LIGHT0, GL_DIFFUSE, x);
    CHECK(eq4x(x, 0x10000, 0x10000, 0x10000, 0x10000));
    glGetLightxv(GL_LIGHT0, GL_SPOT_CUTOFF, x);
    CHECK(x[0] == 180 << 16);
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, f);
    CHECK(eq4(f, 0.2f, 0.2f, 0.2f, 1.0f));
    glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
    CHECK(b == GL_FALSE);
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, f);
    CHECK(eq4(f, 0.2f, 0.2f, 0.2f, 1.0f));
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, f);
    CHECK(eq4(f, 0.8f, 0.8f, 0.8f, 1.0f));
    glGetMaterialfv(GL_FRONT, GL_SPECULAR, f);
    CHECK(eq4(f, 0, 0, 0, 1));
    glGetMaterialfv(GL_BACK, GL_EMISSION, f);
    CHECK(eq4(f, 0, 0, 0, 1));
    CHECK(material1(GL_FRONT, GL_SHININESS) == 0.0f);
    glGetMaterialxv(GL_FRONT, GL_AMBIENT, x);
    CHECK(eq4x(x, 0x3333, 0x3333, 0x3333, 0x10000));
    CHECK(!glIsEnabled(GL_LIGHTING) && !glIsEnabled(GL_COLOR_MATERIAL));
    CHECK_GL(GL_NO_ERROR);

    /* Colors: float and fixed. */
    f[0] = 0.25f;
    f[1] = 0.5f;
    f[2] = 0.75f;
    f[3] = 1.0f;
    glLightfv(GL_LIGHT1, GL_AMBIENT, f);
    CHECK_GL(GL_NO_ERROR);
    glGetLightfv(GL_LIGHT1, GL_AMBIENT, f);
    CHECK(eq4(f, 0.25f, 0.5f, 0.75f, 1.0f));
    glGetLightxv(GL_LIGHT1, GL_AMBIENT, x);
    CHECK(eq4x(x, 0x4000, 0x8000, 0xc000, 0x10000));
    x[0] = 0x20000; /* light colors are not clamped */
    x[1] = 0;
    x[2] = 0x8000;
    x[3] = 0x10000;
    glLightxv(GL_LIGHT2, GL_SPECULAR, x);
    CHECK_GL(GL_NO_ERROR);
    glGetLightfv(GL_LIGHT2, GL_SPECULAR, f);
    CHECK(eq4(f, 2.0f, 0.0f, 0.5f, 1.0f));
    glLightxv(GL_LIGHT2, GL_DIFFUSE, x);
    glGetLightxv(GL_LIGHT2, GL_DIFFUSE, x);
    CHECK(eq4x(x, 0x20000, 0, 0x8000, 0x10000));

    /* Position and spot direction are transformed by the modelview when specified. */
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1.0f, 2.0f, 3.0f);
    f[0] = 1.0f;
    f[1] = 1.0f;
    f[2] = 1.0f;
    f[3] = 1.0f;
    glLightfv(GL_LIGHT3, GL_POSITION, f);
    f[3] = 0.0f; /* directional: translation does not apply */
    glLightfv(GL_LIGHT4, GL_POSITION, f);
    f[0] = 0.0f;
    f[1] = 1.0f;
    f[2] = 0.0f;
    glLightfv(GL_LIGHT3, GL_SPOT_DIRECTION, f);
    CHECK_GL(GL_NO_ERROR);
    glLoadIdentity();
    glGetLightfv(GL_LIGHT3, GL_POSITION, f);
    CHECK(eq4(f, 2.0f, 3.0f, 4.0f, 1.0f));
    glGetLightfv(GL_LIGHT4, GL_POSITION, f);
    CHECK(eq4(f, 1.0f, 1.0f, 1.0f, 0.0f));
    glGetLightfv(GL_LIGHT3, GL_SPOT_DIRECTION, f);
    CHECK(f[0] == 0.0f && f[1] == 1.0f && f[2] == 0.0f);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    x[0] = 0x10000;
    x[1] = 0;
    x[2] = 0;
    x[3] = 0;
    glLightxv(GL_LIGHT5, GL_POSITION, x);
    glLightxv(GL_LIGHT5, GL_SPOT_DIRECTION, x);
    CHECK_GL(GL_NO_ERROR);
    glLoadIdentity();
    glGetLightxv(GL_LIGHT5, GL_POSITION, x);
    CHECK(x[0] >= -1 && x[0] <= 1 && x[1] == 0x10000 && x[2] == 0 && x[3] == 0);
    glGetLightxv(GL_LIGHT5, GL_SPOT_DIRECTION, x);
    CHECK(x[0] >= -1 && x[0] <= 1 && x[1] == 0x10000 && x[2] == 0);

    /* Scalars: ranges are exponent [0, 128], cutoff [0, 90] or 180, attenuation >= 0. */
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 128.0f);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 90.0f);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.0f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 2.0f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.5f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(light1(GL_LIGHT1, GL_SPOT_EXPONENT) == 128.0f);
    CHECK(light1(GL_LIGHT1, GL_SPOT_CUTOFF) == 90.0f);
    CHECK(light1(GL_LIGHT1, GL_CONSTANT_ATTENUATION) == 0.0f);
    CHECK(light1(GL_LIGHT1, GL_LINEAR_ATTENUATION) == 2.0f);
    CHECK(light1(GL_LIGHT1, GL_QUADRATIC_ATTENUATION) == 0.5f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 128.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, -1.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 90.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, -1.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 179.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, -0.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, -0.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, -0.5f);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(light1(GL_LIGHT1, GL_SPOT_EXPONENT) == 128.0f);
    CHECK(light1(GL_LIGHT1, GL_SPOT_CUTOFF) == 90.0f);
    CHECK(light1(GL_LIGHT1, GL_QUADRATIC_ATTENUATION) == 0.5f);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(light1(GL_LIGHT1, GL_SPOT_CUTOFF) == 180.0f);

    glLightx(GL_LIGHT1, GL_SPOT_EXPONENT, 0x8000);
    glLightx(GL_LIGHT1, GL_SPOT_CUTOFF, 45 << 16);
    glLightx(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0x20000);
    CHECK_GL(GL_NO_ERROR);
    glGetLightxv(GL_LIGHT1, GL_SPOT_EXPONENT, x);
    CHECK(x[0] == 0x8000);
    CHECK(light1(GL_LIGHT1, GL_SPOT_CUTOFF) == 45.0f);
    CHECK(light1(GL_LIGHT1, GL_CONSTANT_ATTENUATION) == 2.0f);
    glLightx(GL_LIGHT1, GL_SPOT_EXPONENT, 129 << 16);
    CHECK_GL(GL_INVALID_VALUE);
    glLightx(GL_LIGHT1, GL_SPOT_CUTOFF, 91 << 16);
    CHECK_GL(GL_INVALID_VALUE);
    glLightx(GL_LIGHT1, GL_LINEAR_ATTENUATION, -1);
    CHECK_GL(GL_INVALID_VALUE);
    x[0] = -0x10000;
    glLightxv(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, x);
    CHECK_GL(GL_INVALID_VALUE);
    f[0] = 200.0f;
    glLightfv(GL_LIGHT1, GL_SPOT_EXPONENT, f);
    CHECK_GL(GL_INVALID_VALUE);
    f[0] = 3.0f;
    glLightfv(GL_LIGHT1, GL_SPOT_EXPONENT, f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(light1(GL_LIGHT1, GL_SPOT_EXPONENT) == 3.0f);
    CHECK(light1(GL_LIGHT1, GL_SPOT_CUTOFF) == 45.0f);

    /* Names: lights beyond the limit and unknown parameters are INVALID_ENUM. */
    glLightf(GL_LIGHT0 + (GLenum)max_lights, GL_SPOT_EXPONENT, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glLightx(GL_TEXTURE_2D, GL_SPOT_EXPONENT, 0x10000);
    CHECK_GL(GL_INVALID_ENUM);
    glLightfv(GL_LIGHT0 + (GLenum)max_lights, GL_AMBIENT, f);
    CHECK_GL(GL_INVALID_ENUM);
    glLightxv(GL_LIGHT0 + (GLenum)max_lights, GL_AMBIENT, x);
    CHECK_GL(GL_INVALID_ENUM);
    glLightf(GL_LIGHT0, GL_SHININESS, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glLightfv(GL_LIGHT0, GL_EMISSION, f);
    CHECK_GL(GL_INVALID_ENUM);
    glLightxv(GL_LIGHT0, GL_FOG_COLOR, x);
    CHECK_GL(GL_INVALID_ENUM);
    glLightx(GL_LIGHT0, GL_POINT_SIZE, 0);
    CHECK_GL(GL_INVALID_ENUM);
    if (ct_strict()) {
        glLightf(GL_LIGHT0, GL_AMBIENT, 1.0f);
        CHECK_GL(GL_INVALID_ENUM);
        glLightx(GL_LIGHT0, GL_POSITION, 0x10000);
        CHECK_GL(GL_INVALID_ENUM);
    }
    glGetLightfv(GL_LIGHT0 + (GLenum)max_lights, GL_AMBIENT, f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetLightxv(GL_LIGHT0, GL_SHININESS, x);
    CHECK_GL(GL_INVALID_ENUM);
    glGetLightfv(GL_LIGHT0, GL_AMBIENT_AND_DIFFUSE, f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetLightfv(GL_LIGHT0, GL_DIFFUSE, f);
    CHECK(eq4(f, 1, 1, 1, 1));

    /* Light model. */
    f[0] = 0.5f;
    f[1] = 0.25f;
    f[2] = 0.0f;
    f[3] = 1.0f;
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, f);
    CHECK_GL(GL_NO_ERROR);
    glGetFixedv(GL_LIGHT_MODEL_AMBIENT, x);
    CHECK(eq4x(x, 0x8000, 0x4000, 0, 0x10000));
    glGetIntegerv(GL_LIGHT_MODEL_AMBIENT, iv);
    CHECK(iv[3] == 0x7fffffff && iv[2] == 0);
    x[0] = 0x10000;
    x[1] = 0x10000;
    x[2] = 0x8000;
    x[3] = 0;
    glLightModelxv(GL_LIGHT_MODEL_AMBIENT, x);
    CHECK_GL(GL_NO_ERROR);
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, f);
    CHECK(eq4(f, 1.0f, 1.0f, 0.5f, 0.0f));
    glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1.0f);
    CHECK_GL(GL_NO_ERROR);
    glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
    CHECK(b == GL_TRUE);
    glLightModelx(GL_LIGHT_MODEL_TWO_SIDE, 0);
    glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
    CHECK(b == GL_FALSE);
    x[0] = 0x10000;
    glLightModelxv(GL_LIGHT_MODEL_TWO_SIDE, x);
    glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, iv);
    CHECK(iv[0] == 1);
    f[0] = 0.0f;
    glLightModelfv(GL_LIGHT_MODEL_TWO_SIDE, f);
    CHECK_GL(GL_NO_ERROR);
    glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, iv);
    CHECK(iv[0] == 0);
    glLightModelf(GL_LIGHT0, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glLightModelx(GL_AMBIENT, 0);
    CHECK_GL(GL_INVALID_ENUM);
    glLightModelfv(GL_FOG_COLOR, f);
    CHECK_GL(GL_INVALID_ENUM);
    glLightModelxv(GL_SHININESS, x);
    CHECK_GL(GL_INVALID_ENUM);
    if (ct_strict()) {
        glLightModelf(GL_LIGHT_MODEL_AMBIENT, 1.0f);
        CHECK_GL(GL_INVALID_ENUM);
        glLightModelx(GL_LIGHT_MODEL_AMBIENT, 0x10000);
        CHECK_GL(GL_INVALID_ENUM);
    }
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, f);
    CHECK(eq4(f, 1.0f, 1.0f, 0.5f, 0.0f));

    /* Material: set for FRONT_AND_BACK only, read for FRONT or BACK. */
    f[0] = 0.1f;
    f[1] = 0.2f;
    f[2] = 0.3f;
    f[3] = 0.4f;
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, f);
    CHECK_GL(GL_NO_ERROR);
    glGetMaterialfv(GL_FRONT, GL_SPECULAR, f);
    CHECK(eq4(f, 0.1f, 0.2f, 0.3f, 0.4f));
    glGetMaterialfv(GL_BACK, GL_EMISSION, f);
    CHECK(eq4(f, 0.1f, 0.2f, 0.3f, 0.4f));
    f[0] = 0.5f;
    f[1] = 0.5f;
    f[2] = 0.0f;
    f[3] = 1.0f;
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, f);
    CHECK_GL(GL_NO_ERROR);
    glGetMaterialxv(GL_FRONT, GL_AMBIENT, x);
    CHECK(eq4x(x, 0x8000, 0x8000, 0, 0x10000));
    glGetMaterialxv(GL_BACK, GL_DIFFUSE, x);
    CHECK(eq4x(x, 0x8000, 0x8000, 0, 0x10000));
    x[0] = 0x4000;
    x[1] = 0;
    x[2] = 0;
    x[3] = 0x10000;
    glMaterialxv(GL_FRONT_AND_BACK, GL_DIFFUSE, x);
    CHECK_GL(GL_NO_ERROR);
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, f);
    CHECK(eq4(f, 0.25f, 0, 0, 1));
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, f);
    CHECK(eq4(f, 0.5f, 0.5f, 0, 1));
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(material1(GL_BACK, GL_SHININESS) == 64.0f);
    glMaterialx(GL_FRONT_AND_BACK, GL_SHININESS, 0x8000);
    CHECK_GL(GL_NO_ERROR);
    glGetMaterialxv(GL_FRONT, GL_SHININESS, x);
    CHECK(x[0] == 0x8000);
    x[0] = 128 << 16;
    glMaterialxv(GL_FRONT_AND_BACK, GL_SHININESS, x);
    CHECK(material1(GL_FRONT, GL_SHININESS) == 128.0f);
    f[0] = 10.0f;
    glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(material1(GL_FRONT, GL_SHININESS) == 10.0f);

    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 128.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, -1.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glMaterialx(GL_FRONT_AND_BACK, GL_SHININESS, 129 << 16);
    CHECK_GL(GL_INVALID_VALUE);
    f[0] = -0.5f;
    glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, f);
    CHECK_GL(GL_INVALID_VALUE);
    x[0] = -1;
    glMaterialxv(GL_FRONT_AND_BACK, GL_SHININESS, x);
    CHECK_GL(GL_INVALID_VALUE);
    glMaterialf(GL_FRONT, GL_SHININESS, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialx(GL_BACK, GL_SHININESS, 0x10000);
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialfv(GL_FRONT, GL_AMBIENT, f);
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialxv(GL_BACK, GL_AMBIENT, x);
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialf(GL_FRONT_AND_BACK, GL_SPOT_EXPONENT, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glMaterialfv(GL_FRONT_AND_BACK, GL_POSITION, f);
    CHECK_GL(GL_INVALID_ENUM);
    if (ct_strict()) {
        glMaterialf(GL_FRONT_AND_BACK, GL_AMBIENT, 1.0f);
        CHECK_GL(GL_INVALID_ENUM);
        glMaterialx(GL_FRONT_AND_BACK, GL_EMISSION, 0);
        CHECK_GL(GL_INVALID_ENUM);
    }
    CHECK(material1(GL_FRONT, GL_SHININESS) == 10.0f);
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, f);
    CHECK(eq4(f, 0.5f, 0.5f, 0, 1));
    glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetMaterialxv(GL_FRONT_AND_BACK, GL_SHININESS, x);
    CHECK_GL(GL_INVALID_ENUM);
    glGetMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetMaterialxv(GL_BACK, GL_POSITION, x);
    CHECK_GL(GL_INVALID_ENUM);

    /* Color material: the current color becomes the ambient and diffuse material when
     * enabled and while enabled; disabling keeps the last values. */
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glEnable(GL_COLOR_MATERIAL);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsEnabled(GL_COLOR_MATERIAL));
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, f);
    CHECK(eq4(f, 0.25f, 0.5f, 0.75f, 1.0f));
    glColor4x(0x10000, 0, 0x8000, 0x10000);
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, f);
    CHECK(eq4(f, 1.0f, 0.0f, 0.5f, 1.0f));
    glDisable(GL_COLOR_MATERIAL);
    glColor4f(0, 0, 0, 0);
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, f);
    CHECK(eq4(f, 1.0f, 0.0f, 0.5f, 1.0f));
    glGetMaterialfv(GL_FRONT, GL_SPECULAR, f);
    CHECK(eq4(f, 0.1f, 0.2f, 0.3f, 0.4f));

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0 + (GLenum)max_lights - 1);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsEnabled(GL_LIGHTING) && glIsEnabled(GL_LIGHT0 + (GLenum)max_lights - 1));
    glEnable(GL_LIGHT0 + (GLenum)max_lights);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
