/*
 * GL_EXT_polygon_offset_clamp: glPolygonOffsetClampEXT sets factor, units and clamp;
 * glPolygonOffset sets the clamp to 0. A positive clamp bounds the offset from above, a
 * negative one from below, 0 not at all: a quad drawn again over itself with an offset of
 * ±1000 depth steps passes GREATER / LESS without a clamp and fails with a clamp of ±1e-12
 * (far below one step of the 24-bit buffer, so the clamped depth is the stored one).
 */
#include "common.h"

static PFNGLPOLYGONOFFSETCLAMPEXTPROC glPolygonOffsetClampEXT;

static void quad(GLfloat r, GLfloat g, GLfloat b)
{
    /* z = 0.25: window depth 0.625, 0.375 of a step from the nearest step boundary of the
     * 24-bit buffer, so a 1e-12 change leaves the stored value alone. */
    static const GLfloat v[12] = {-1, -1, 0.25f, 1, -1, 0.25f, -1, 1, 0.25f, 1, 1, 0.25f};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColor4f(r, g, b, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

/* Green, then red offset by `units` steps under `func`; the center's color. */
static void redraw(GLenum func, GLfloat units, GLfloat clamp, int expect_red)
{
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_ALWAYS);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    quad(0, 1, 0);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffsetClampEXT(0, units, clamp);
    glDepthFunc(func);
    quad(1, 0, 0);
    if (expect_red)
        CHECK_PIXEL(4, 4, 255, 0, 0, 255, 0);
    else
        CHECK_PIXEL(4, 4, 0, 255, 0, 255, 0);
}

int main(void)
{
    GLfloat f[3] = {-1, -1, -1};
    int listed;

    ct_init(8, 8);
    glPolygonOffsetClampEXT =
        (PFNGLPOLYGONOFFSETCLAMPEXTPROC)eglGetProcAddress("glPolygonOffsetClampEXT");
    listed = strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_polygon_offset_clamp") !=
             NULL;
    /* Ours lists it; of Mesa's drivers llvmpipe does and softpipe does not (there the
     * program ends here). */
    if (ct_strict())
        CHECK(listed && glPolygonOffsetClampEXT != NULL);
    if (!listed || glPolygonOffsetClampEXT == NULL)
        return ct_done();

    glGetFloatv(GL_POLYGON_OFFSET_CLAMP_EXT, f);
    CHECK(f[0] == 0);
    glPolygonOffsetClampEXT(1.5f, 2.5f, -0.25f);
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &f[0]);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &f[1]);
    glGetFloatv(GL_POLYGON_OFFSET_CLAMP_EXT, &f[2]);
    CHECK(f[0] == 1.5f && f[1] == 2.5f && f[2] == -0.25f);
    glPolygonOffset(1, 1);
    glGetFloatv(GL_POLYGON_OFFSET_CLAMP_EXT, &f[2]);
    CHECK(f[2] == 0);
    CHECK_GL(GL_NO_ERROR);

    glEnable(GL_DEPTH_TEST);
    redraw(GL_LESS, -1000, 0, 1);
    redraw(GL_LESS, -1000, -1e-12f, 0);
    redraw(GL_LESS, -1000, 1e-12f, 1); /* a positive clamp bounds only from above */
    redraw(GL_GREATER, 1000, 0, 1);
    redraw(GL_GREATER, 1000, 1e-12f, 0);
    redraw(GL_GREATER, 1000, -1e-12f, 1);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
