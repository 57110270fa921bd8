/* Point and line state: widths, sizes, point parameters and the size ranges. */
#include "common.h"

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

static GLint geti(GLenum pname)
{
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
}

int main(void)
{
    GLfloat range[2], f3[3];
    GLfixed x3[3];
    GLint i3[3];
    GLfloat max_point;

    ct_init(16, 16);

    /* Ranges: at least 1..1, minimum 1 for aliased primitives. */
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, range);
    CHECK(range[0] <= 1.0f && range[1] >= 1.0f && range[0] <= range[1]);
    max_point = range[1];
    glGetFloatv(GL_SMOOTH_POINT_SIZE_RANGE, range);
    CHECK(range[0] <= 1.0f && range[1] >= 1.0f);
    if (range[1] > max_point)
        max_point = range[1];
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    CHECK(range[0] <= 1.0f && range[1] >= 1.0f);
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, range);
    CHECK(range[0] <= 1.0f && range[1] >= 1.0f);
    glGetIntegerv(GL_ALIASED_POINT_SIZE_RANGE, i3);
    CHECK(i3[0] <= 1 && i3[1] >= 1);
    CHECK_GL(GL_NO_ERROR);

    /* Defaults. */
    CHECK(getf(GL_LINE_WIDTH) == 1.0f);
    CHECK(getf(GL_POINT_SIZE) == 1.0f);
    CHECK(getx(GL_POINT_SIZE) == 0x10000);
    CHECK(getf(GL_POINT_SIZE_MIN) == 0.0f);
    CHECK(getf(GL_POINT_SIZE_MAX) == max_point);
    CHECK(getf(GL_POINT_FADE_THRESHOLD_SIZE) == 1.0f);
    glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, f3);
    CHECK(f3[0] == 1.0f && f3[1] == 0.0f && f3[2] == 0.0f);
    CHECK_GL(GL_NO_ERROR);

    /* Line width: > 0, else INVALID_VALUE and no change. */
    glLineWidth(2.5f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_LINE_WIDTH) == 2.5f);
    CHECK(getx(GL_LINE_WIDTH) == 0x28000);
    CHECK(geti(GL_LINE_WIDTH) == 3 || geti(GL_LINE_WIDTH) == 2);
    glLineWidth(0.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glLineWidth(-1.0f);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(getf(GL_LINE_WIDTH) == 2.5f);
    glLineWidthx(0x30000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_LINE_WIDTH) == 3.0f);
    glLineWidthx(0);
    CHECK_GL(GL_INVALID_VALUE);
    glLineWidthx(-0x10000);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(geti(GL_LINE_WIDTH) == 3);

    /* Point size: > 0, else INVALID_VALUE. */
    glPointSize(4.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POINT_SIZE) == 4.0f);
    glPointSize(0.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glPointSize(-2.0f);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(getf(GL_POINT_SIZE) == 4.0f);
    glPointSizex(0x18000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POINT_SIZE) == 1.5f);
    CHECK(getx(GL_POINT_SIZE) == 0x18000);
    glPointSizex(0);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(getx(GL_POINT_SIZE) == 0x18000);

    /* Point parameters. */
    glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POINT_SIZE_MIN) == 2.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 8.0f);
    CHECK(getf(GL_POINT_SIZE_MAX) == 8.0f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 0.5f);
    CHECK(getf(GL_POINT_FADE_THRESHOLD_SIZE) == 0.5f);
    CHECK_GL(GL_NO_ERROR);
    glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glPointParameterf(GL_POINT_SIZE_MAX, -1.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -0.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glPointParameterf(GL_POINT_SIZE, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(getf(GL_POINT_SIZE_MIN) == 2.0f);
    CHECK(getf(GL_POINT_SIZE_MAX) == 8.0f);
    CHECK(getf(GL_POINT_FADE_THRESHOLD_SIZE) == 0.5f);

    glPointParameterx(GL_POINT_SIZE_MIN, 0x8000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POINT_SIZE_MIN) == 0.5f);
    CHECK(getx(GL_POINT_SIZE_MIN) == 0x8000);
    glPointParameterx(GL_POINT_SIZE_MAX, -0x10000);
    CHECK_GL(GL_INVALID_VALUE);
    glPointParameterx(GL_LINE_WIDTH, 0x10000);
    CHECK_GL(GL_INVALID_ENUM);
    glPointParameterx(GL_POINT_FADE_THRESHOLD_SIZE, 0x20000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getx(GL_POINT_FADE_THRESHOLD_SIZE) == 0x20000);

    f3[0] = 0.0f;
    f3[1] = 0.5f;
    f3[2] = 0.25f;
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, f3);
    CHECK_GL(GL_NO_ERROR);
    glGetFixedv(GL_POINT_DISTANCE_ATTENUATION, x3);
    CHECK(x3[0] == 0 && x3[1] == 0x8000 && x3[2] == 0x4000);
    f3[0] = 3.0f;
    glPointParameterfv(GL_POINT_SIZE_MAX, f3);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POINT_SIZE_MAX) == 3.0f);
    f3[0] = -3.0f;
    glPointParameterfv(GL_POINT_SIZE_MAX, f3);
    CHECK_GL(GL_INVALID_VALUE);
    glPointParameterfv(GL_FOG_DENSITY, f3);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(getf(GL_POINT_SIZE_MAX) == 3.0f);

    x3[0] = 0x10000;
    x3[1] = 0x20000;
    x3[2] = 0x30000;
    glPointParameterxv(GL_POINT_DISTANCE_ATTENUATION, x3);
    CHECK_GL(GL_NO_ERROR);
    glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, f3);
    CHECK(f3[0] == 1.0f && f3[1] == 2.0f && f3[2] == 3.0f);
    glGetIntegerv(GL_POINT_DISTANCE_ATTENUATION, i3);
    CHECK(i3[0] == 1 && i3[1] == 2 && i3[2] == 3);
    x3[0] = 0x40000;
    glPointParameterxv(GL_POINT_SIZE_MIN, x3);
    CHECK(getf(GL_POINT_SIZE_MIN) == 4.0f);
    x3[0] = -1;
    glPointParameterxv(GL_POINT_SIZE_MIN, x3);
    CHECK_GL(GL_INVALID_VALUE);
    glPointParameterxv(GL_POINT_SIZE_ARRAY_OES, x3);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(getf(GL_POINT_SIZE_MIN) == 4.0f);

    /* The capabilities of this area. */
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SPRITE_OES);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsEnabled(GL_POINT_SMOOTH) && glIsEnabled(GL_LINE_SMOOTH) &&
          glIsEnabled(GL_POINT_SPRITE_OES));
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
