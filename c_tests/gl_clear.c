/*
 * glClear and its state: clear values (float, fixed, clamped), the color, depth and stencil
 * write masks, the scissor test, and the one error glClear raises. Cleared colors are exact:
 * 0 and 1 map to 0 and 255, and 0.4 converts to 102 in 8 bits (0.4 x 255 = 102.0).
 */
#include "common.h"

static void draw_rect(GLfloat z, GLfloat r, GLfloat g, GLfloat b)
{
    GLfloat v[12] = {-1, -1, z, 1, -1, z, 1, 1, z, -1, 1, z};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColor4f(r, g, b, 1);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

int main(void)
{
    GLfloat f[4];
    GLint i[4];
    GLfixed x[4];

    ct_init(32, 32);

    /* Initial values. */
    glGetFloatv(GL_COLOR_CLEAR_VALUE, f);
    CHECK(f[0] == 0 && f[1] == 0 && f[2] == 0 && f[3] == 0);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, f);
    CHECK(f[0] == 1);
    glGetIntegerv(GL_STENCIL_CLEAR_VALUE, i);
    CHECK(i[0] == 0);
    glGetIntegerv(GL_STENCIL_WRITEMASK, i);
    CHECK((i[0] & 0xFF) == 0xFF); /* all ones (at least in the 8 stencil bits) */

    /* Clear values are clamped to [0, 1] when specified. */
    glClearColor(-1, 0.25f, 2, 0.5f);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, f);
    CHECK_MESA_DEVIATES(f[0] == 0 && f[1] == 0.25f && f[2] == 1 && f[3] == 0.5f,
                        "keeps clear colors unclamped");
    glClearColorx(0x10000, 0x8000, 0, 0x20000);
    glGetFixedv(GL_COLOR_CLEAR_VALUE, x);
    CHECK_MESA_DEVIATES(x[0] == 0x10000 && x[1] == 0x8000 && x[2] == 0 && x[3] == 0x10000,
                        "keeps clear colors unclamped");
    glClearDepthf(3);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, f);
    CHECK(f[0] == 1);
    glClearDepthx(0x4000);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, f);
    CHECK(f[0] == 0.25f);
    glClearStencil(5);
    glGetIntegerv(GL_STENCIL_CLEAR_VALUE, i);
    CHECK(i[0] == 5);
    CHECK_GL(GL_NO_ERROR);

    /* Color. */
    glClearColor(0.4f, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(0, 0, 102, 0, 255, 255, 0);
    CHECK_PIXEL(31, 31, 102, 0, 255, 255, 0);

    /* Color mask: green and alpha kept. */
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glGetIntegerv(GL_COLOR_WRITEMASK, i);
    CHECK(i[0] == 0 && i[1] == 1 && i[2] == 0 && i[3] == 1);
    glClearColor(1, 1, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(5, 5, 102, 255, 255, 0, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* Scissor: only the box [8, 24) x [4, 12) is cleared. */
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(8, 4, 16, 8);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(8, 4, 255, 255, 255, 255, 0);
    CHECK_PIXEL(23, 11, 255, 255, 255, 255, 0);
    CHECK_PIXEL(7, 4, 0, 0, 0, 255, 0);
    CHECK_PIXEL(24, 4, 0, 0, 0, 255, 0);
    CHECK_PIXEL(8, 3, 0, 0, 0, 255, 0);
    CHECK_PIXEL(8, 12, 0, 0, 0, 255, 0);
    ct_save("scissor");
    glDisable(GL_SCISSOR_TEST);

    /* Depth: clear to 0.5, then quads at window depth 0.75 (hidden) and 0.25 (shown). */
    glClearColor(0, 0, 0, 1);
    glClearDepthf(0.5f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    draw_rect(0.5f, 1, 0, 0); /* ndc z 0.5 -> window 0.75 */
    CHECK_PIXEL(16, 16, 0, 0, 0, 255, 0);
    draw_rect(-0.5f, 0, 1, 0); /* window 0.25 */
    CHECK_PIXEL(16, 16, 0, 255, 0, 255, 0);

    /* Depth mask off: clearing depth to 0 changes nothing, the stored 0.25 stays. */
    glDepthMask(GL_FALSE);
    glGetIntegerv(GL_DEPTH_WRITEMASK, i);
    CHECK(i[0] == GL_FALSE);
    glClearDepthf(0);
    glClear(GL_DEPTH_BUFFER_BIT);
    draw_rect(-0.6f, 0, 0, 1); /* window 0.2 < 0.25: passes */
    CHECK_PIXEL(16, 16, 0, 0, 255, 255, 0);
    glDepthMask(GL_TRUE);

    /* Depth cleared under a scissor box only inside it. */
    glClearDepthf(0);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 8, 32);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    draw_rect(-0.8f, 1, 1, 0); /* window 0.1: hidden left of x = 8, shown right of it */
    CHECK_PIXEL(4, 16, 0, 0, 255, 255, 0);
    CHECK_PIXEL(12, 16, 255, 255, 0, 255, 0);
    glDisable(GL_DEPTH_TEST);

    /* Stencil mask state (its effect on pixels is the stencil test's). */
    glStencilMask(0x0F);
    glGetIntegerv(GL_STENCIL_WRITEMASK, i);
    CHECK(i[0] == 0x0F);
    glClear(GL_STENCIL_BUFFER_BIT);
    CHECK_GL(GL_NO_ERROR);

    /* The one error: bits other than the three buffer bits; nothing is cleared. */
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | 0x8000);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK_PIXEL(12, 16, 255, 255, 0, 255, 0);
    glClear(0);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
