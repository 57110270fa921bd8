/*
 * Clipping in pixels: user clip planes set under a scaled modelview (stored in eye space,
 * queried back), every available plane at once, lines and points against a plane, a floor
 * crossing the near plane in perspective, and triangles entirely behind the eye (w < 0).
 * Constant colors, so every covered pixel is exact.
 */
#include "common.h"

static void ortho(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, 32, 0, 32, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void full_quad(void)
{
    static const GLfloat v[8] = {0, 0, 32, 0, 0, 32, 32, 32};
    glVertexPointer(2, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

int main(void)
{
    GLint max_planes = 0, i;
    ct_init(32, 32);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor4f(1, 1, 1, 1);

    /* Object plane x >= 4 set under scale 2 is eye plane x >= 8. */
    ortho();
    glScalef(2, 2, 1);
    {
        static const GLfloat eq[4] = {1, 0, 0, -4};
        GLfloat got[4];
        glClipPlanef(GL_CLIP_PLANE0, eq);
        glGetClipPlanef(GL_CLIP_PLANE0, got);
        CHECK(got[0] == 0.5f && got[1] == 0 && got[2] == 0 && got[3] == -4);
    }
    glLoadIdentity();
    glEnable(GL_CLIP_PLANE0);
    full_quad();
    CHECK_PIXEL(7, 16, 0, 0, 0, 0, 0);
    CHECK_PIXEL(8, 16, 255, 255, 255, 255, 0);
    CHECK_PIXEL(31, 0, 255, 255, 255, 255, 0);
    ct_save("plane_scaled");

    /* Lines and points: a horizontal line across the plane keeps only its right part; a
     * point whose center is outside is dropped, one inside is drawn. */
    ortho();
    {
        static const GLfloat line[4] = {0.5f, 10.5f, 31.5f, 10.5f};
        static const GLfloat pts[4] = {5.5f, 20.5f, 12.5f, 20.5f};
        glVertexPointer(2, GL_FLOAT, 0, line);
        glDrawArrays(GL_LINES, 0, 2);
        CHECK_PIXEL(4, 10, 0, 0, 0, 0, 0);
        CHECK_PIXEL(12, 10, 255, 255, 255, 255, 0);
        glPointSize(5);
        glVertexPointer(2, GL_FLOAT, 0, pts);
        glDrawArrays(GL_POINTS, 0, 2);
        CHECK_PIXEL(5, 20, 0, 0, 0, 0, 0);
        CHECK_PIXEL(12, 20, 255, 255, 255, 255, 0);
        glPointSize(1);
        ct_save("lines_points");
    }
    glDisable(GL_CLIP_PLANE0);

    /* Every plane the implementation has, cutting a box [8, 24) in x and y (planes beyond
     * the fourth repeat x >= 8). */
    glGetIntegerv(GL_MAX_CLIP_PLANES, &max_planes);
    CHECK(max_planes >= 6);
    ortho();
    for (i = 0; i < max_planes; ++i) {
        GLfloat eq[4][4] = {{1, 0, 0, -8}, {-1, 0, 0, 24}, {0, 1, 0, -8}, {0, -1, 0, 24}};
        glClipPlanef(GL_CLIP_PLANE0 + i, eq[i < 4 ? i : 0]);
        glEnable(GL_CLIP_PLANE0 + i);
    }
    full_quad();
    CHECK_PIXEL(8, 8, 255, 255, 255, 255, 0);
    CHECK_PIXEL(23, 23, 255, 255, 255, 255, 0);
    CHECK_PIXEL(7, 16, 0, 0, 0, 0, 0);
    CHECK_PIXEL(24, 16, 0, 0, 0, 0, 0);
    CHECK_PIXEL(16, 7, 0, 0, 0, 0, 0);
    CHECK_PIXEL(16, 24, 0, 0, 0, 0, 0);
    ct_save("all_planes");
    for (i = 0; i < max_planes; ++i)
        glDisable(GL_CLIP_PLANE0 + i);

    /* Perspective: a floor at y = -1 from behind the eye to far ahead crosses the near
     * plane and covers the lower half of the screen; the upper half stays clear. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustumf(-1, 1, -1, 1, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClear(GL_COLOR_BUFFER_BIT);
    {
        static const GLfloat floor_v[9] = {-50, -1, 10, 50, -1, 10, 0, -1, -90};
        static const GLfloat behind[9] = {-5, -5, 2, 5, -5, 2, 0, 5, 3};
        glVertexPointer(3, GL_FLOAT, 0, floor_v);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        CHECK_PIXEL(16, 0, 255, 255, 255, 255, 0);
        CHECK_PIXEL(16, 14, 255, 255, 255, 255, 0);
        CHECK_PIXEL(16, 17, 0, 0, 0, 0, 0);
        CHECK_PIXEL(16, 31, 0, 0, 0, 0, 0);
        ct_save("near_crossing");
        /* Entirely behind the eye: nothing. */
        glClear(GL_COLOR_BUFFER_BIT);
        glVertexPointer(3, GL_FLOAT, 0, behind);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        CHECK_PIXEL(16, 16, 0, 0, 0, 0, 0);
        CHECK_PIXEL(0, 0, 0, 0, 0, 0, 0);
        CHECK_PIXEL(31, 31, 0, 0, 0, 0, 0);
    }
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
