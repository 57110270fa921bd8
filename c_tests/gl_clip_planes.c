/* User clip planes: specification in object coordinates, storage in eye coordinates. */
#include "common.h"

static int plane_is(const GLfloat *p, GLfloat a, GLfloat b, GLfloat c, GLfloat d)
{
    return p[0] == a && p[1] == b && p[2] == c && p[3] == d;
}

int main(void)
{
    GLint max_planes = 0, i;
    GLfloat eq[4], got[4];
    GLfixed eqx[4], gotx[4];

    ct_init(16, 16);

    glGetIntegerv(GL_MAX_CLIP_PLANES, &max_planes);
    CHECK(max_planes >= 1);
    CHECK_GL(GL_NO_ERROR);

    /* Every plane starts as (0, 0, 0, 0) and disabled. */
    for (i = 0; i < max_planes; ++i) {
        got[0] = got[1] = got[2] = got[3] = 9.0f;
        glGetClipPlanef(GL_CLIP_PLANE0 + i, got);
        CHECK(plane_is(got, 0, 0, 0, 0));
        CHECK(!glIsEnabled(GL_CLIP_PLANE0 + i));
    }
    CHECK_GL(GL_NO_ERROR);

    /* Identity modelview: stored as given. */
    eq[0] = 1.0f;
    eq[1] = 0.0f;
    eq[2] = 0.0f;
    eq[3] = 0.5f;
    glClipPlanef(GL_CLIP_PLANE0, eq);
    CHECK_GL(GL_NO_ERROR);
    glGetClipPlanef(GL_CLIP_PLANE0, got);
    CHECK(plane_is(got, 1.0f, 0.0f, 0.0f, 0.5f));
    glGetClipPlanex(GL_CLIP_PLANE0, gotx);
    CHECK(gotx[0] == 0x10000 && gotx[1] == 0 && gotx[2] == 0 && gotx[3] == 0x8000);

    /* A translated modelview: the plane is multiplied by its inverse, so z >= -1 in
     * object coordinates is ze >= -6 in eye coordinates. */
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -5.0f);
    eq[0] = 0.0f;
    eq[1] = 0.0f;
    eq[2] = 1.0f;
    eq[3] = 1.0f;
    glClipPlanef(GL_CLIP_PLANE0 + max_planes - 1, eq);
    CHECK_GL(GL_NO_ERROR);
    glGetClipPlanef(GL_CLIP_PLANE0 + max_planes - 1, got);
    CHECK(plane_is(got, 0.0f, 0.0f, 1.0f, 6.0f));
    /* Changing the modelview later does not change the stored plane. */
    glLoadIdentity();
    glGetClipPlanef(GL_CLIP_PLANE0 + max_planes - 1, got);
    CHECK(plane_is(got, 0.0f, 0.0f, 1.0f, 6.0f));

    /* Fixed point, with a scale: x >= 1 in object space, scaled by 2, is xe >= 2:
     * (1, 0, 0, -1) M^-1 = (0.5, 0, 0, -1). */
    glScalef(2.0f, 2.0f, 2.0f);
    eqx[0] = 0x10000;
    eqx[1] = 0;
    eqx[2] = 0;
    eqx[3] = -0x10000;
    glClipPlanex(GL_CLIP_PLANE0 + 1, eqx);
    CHECK_GL(GL_NO_ERROR);
    glGetClipPlanex(GL_CLIP_PLANE0 + 1, gotx);
    CHECK(gotx[0] == 0x8000 && gotx[1] == 0 && gotx[2] == 0 && gotx[3] == -0x10000);
    glGetClipPlanef(GL_CLIP_PLANE0 + 1, got);
    CHECK(plane_is(got, 0.5f, 0.0f, 0.0f, -1.0f));
    glLoadIdentity();

    /* Planes beyond the limit (or other names) are INVALID_ENUM and change nothing. */
    glClipPlanef(GL_CLIP_PLANE0 + max_planes, eq);
    CHECK_GL(GL_INVALID_ENUM);
    glClipPlanef(GL_LIGHT0, eq);
    CHECK_GL(GL_INVALID_ENUM);
    glClipPlanex(GL_CLIP_PLANE0 + max_planes, eqx);
    CHECK_GL(GL_INVALID_ENUM);
    glClipPlanex(GL_TEXTURE_2D, eqx);
    CHECK_GL(GL_INVALID_ENUM);
    glGetClipPlanef(GL_CLIP_PLANE0 + max_planes, got);
    CHECK_GL(GL_INVALID_ENUM);
    glGetClipPlanex(GL_CLIP_PLANE0 - 1, gotx);
    CHECK_GL(GL_INVALID_ENUM);
    glGetClipPlanef(GL_CLIP_PLANE0, got);
    CHECK(plane_is(got, 1.0f, 0.0f, 0.0f, 0.5f));

    /* Enables. */
    glEnable(GL_CLIP_PLANE0 + max_planes - 1);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsEnabled(GL_CLIP_PLANE0 + max_planes - 1));
    glEnable(GL_CLIP_PLANE0 + max_planes);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
