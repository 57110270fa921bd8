/*
 * Server state and its queries: every glEnable capability with its initial value, glHint,
 * the comparison/cull/winding/shading enums, glViewport (clamped to GL_MAX_VIEWPORT_DIMS),
 * glScissor, glDepthRange (f and x, clamped), glGetString, the four glGet variants' type
 * conversions, the single sticky error flag, glFlush and glFinish — and every error these
 * calls raise.
 */
#include "common.h"

struct cap {
    GLenum cap;
    GLboolean initial;
};

int main(void)
{
    static const struct cap caps[] = {
        {GL_ALPHA_TEST, GL_FALSE}, {GL_BLEND, GL_FALSE}, {GL_COLOR_LOGIC_OP, GL_FALSE},
        {GL_CLIP_PLANE0, GL_FALSE}, {GL_COLOR_MATERIAL, GL_FALSE}, {GL_CULL_FACE, GL_FALSE},
        {GL_DEPTH_TEST, GL_FALSE}, {GL_DITHER, GL_TRUE}, {GL_FOG, GL_FALSE},
        {GL_LIGHT0, GL_FALSE}, {GL_LIGHT7, GL_FALSE}, {GL_LIGHTING, GL_FALSE},
        {GL_LINE_SMOOTH, GL_FALSE}, {GL_MULTISAMPLE, GL_TRUE}, {GL_NORMALIZE, GL_FALSE},
        {GL_POINT_SMOOTH, GL_FALSE}, {GL_POLYGON_OFFSET_FILL, GL_FALSE},
        {GL_RESCALE_NORMAL, GL_FALSE}, {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_FALSE},
        {GL_SAMPLE_ALPHA_TO_ONE, GL_FALSE}, {GL_SAMPLE_COVERAGE, GL_FALSE},
        {GL_SCISSOR_TEST, GL_FALSE}, {GL_STENCIL_TEST, GL_FALSE}, {GL_TEXTURE_2D, GL_FALSE},
    };
    static const GLenum hints[] = {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT,
                                   GL_LINE_SMOOTH_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT};
    GLint iv[4], max_dims[2];
    GLfloat fv[4];
    GLfixed xv[4];
    GLboolean bv[4];
    const char *s;
    size_t k;

    ct_init(32, 16);

    for (k = 0; k < sizeof caps / sizeof caps[0]; ++k) {
        GLenum c = caps[k].cap;
        CHECK(glIsEnabled(c) == caps[k].initial);
        glEnable(c);
        CHECK(glIsEnabled(c) == GL_TRUE);
        glGetBooleanv(c, bv);
        CHECK(bv[0] == GL_TRUE);
        glDisable(c);
        CHECK(glIsEnabled(c) == GL_FALSE);
        glGetIntegerv(c, iv);
        CHECK(iv[0] == 0);
        if (caps[k].initial)
            glEnable(c);
        CHECK_GL(GL_NO_ERROR);
    }
    glEnable(GL_TRIANGLES);
    CHECK_GL(GL_INVALID_ENUM);
    glDisable(0x0B44 + 0x1000);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(glIsEnabled(GL_VERTEX_ARRAY + 0x100) == GL_FALSE);
    CHECK_GL(GL_INVALID_ENUM);
    /* Client-side arrays are queried with glIsEnabled, never set with glEnable. */
    CHECK(glIsEnabled(GL_VERTEX_ARRAY) == GL_FALSE);
    CHECK_GL(GL_NO_ERROR);
    glEnable(GL_VERTEX_ARRAY);
    CHECK_MESA_DEVIATES(glGetError() == GL_INVALID_ENUM, "accepts it, as desktop GL 1.x does");

    for (k = 0; k < sizeof hints / sizeof hints[0]; ++k) {
        glGetIntegerv(hints[k], iv);
        CHECK(iv[0] == GL_DONT_CARE);
        glHint(hints[k], GL_NICEST);
        glGetIntegerv(hints[k], iv);
        CHECK(iv[0] == GL_NICEST);
        glHint(hints[k], GL_FASTEST);
        glGetIntegerv(hints[k], iv);
        CHECK(iv[0] == GL_FASTEST);
    }
    CHECK_GL(GL_NO_ERROR);
    glHint(GL_FOG, GL_NICEST);
    CHECK_GL(GL_INVALID_ENUM);
    glHint(GL_FOG_HINT, GL_FOG);
    CHECK_GL(GL_INVALID_ENUM);

    /* Depth function, culling, winding, shading. */
    glGetIntegerv(GL_DEPTH_FUNC, iv);
    CHECK(iv[0] == GL_LESS);
    glDepthFunc(GL_GEQUAL);
    glGetIntegerv(GL_DEPTH_FUNC, iv);
    CHECK(iv[0] == GL_GEQUAL);
    glDepthFunc(GL_LESS + 8);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_CULL_FACE_MODE, iv);
    CHECK(iv[0] == GL_BACK);
    glCullFace(GL_FRONT_AND_BACK);
    glGetIntegerv(GL_CULL_FACE_MODE, iv);
    CHECK(iv[0] == GL_FRONT_AND_BACK);
    glCullFace(GL_CW);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_FRONT_FACE, iv);
    CHECK(iv[0] == GL_CCW);
    glFrontFace(GL_CW);
    glGetIntegerv(GL_FRONT_FACE, iv);
    CHECK(iv[0] == GL_CW);
    glFrontFace(GL_BACK);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_SHADE_MODEL, iv);
    CHECK(iv[0] == GL_SMOOTH);
    glShadeModel(GL_FLAT);
    glGetIntegerv(GL_SHADE_MODEL, iv);
    CHECK(iv[0] == GL_FLAT);
    glShadeModel(GL_FLOAT);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_SHADE_MODEL, iv);
    CHECK(iv[0] == GL_FLAT);

    /* Viewport and scissor start at the surface size. */
    glGetIntegerv(GL_VIEWPORT, iv);
    CHECK(iv[0] == 0 && iv[1] == 0 && iv[2] == 32 && iv[3] == 16);
    glGetIntegerv(GL_SCISSOR_BOX, iv);
    CHECK(iv[0] == 0 && iv[1] == 0 && iv[2] == 32 && iv[3] == 16);
    glViewport(-5, 3, 7, 9);
    glGetIntegerv(GL_VIEWPORT, iv);
    CHECK(iv[0] == -5 && iv[1] == 3 && iv[2] == 7 && iv[3] == 9);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_dims);
    CHECK(max_dims[0] >= 32 && max_dims[1] >= 16);
    glViewport(0, 0, max_dims[0] + 100, max_dims[1] + 1);
    glGetIntegerv(GL_VIEWPORT, iv);
    CHECK(iv[2] == max_dims[0] && iv[3] == max_dims[1]);
    glViewport(0, 0, -1, 4);
    CHECK_GL(GL_INVALID_VALUE);
    glViewport(0, 0, 4, -1);
    CHECK_GL(GL_INVALID_VALUE);
    glGetIntegerv(GL_VIEWPORT, iv);
    CHECK(iv[2] == max_dims[0]);
    glScissor(1, 2, 3, 4);
    glGetIntegerv(GL_SCISSOR_BOX, iv);
    CHECK(iv[0] == 1 && iv[1] == 2 && iv[2] == 3 && iv[3] == 4);
    glScissor(0, 0, -3, 4);
    CHECK_GL(GL_INVALID_VALUE);
    glScissor(0, 0, 3, -4);
    CHECK_GL(GL_INVALID_VALUE);
    glGetIntegerv(GL_SCISSOR_BOX, iv);
    CHECK(iv[2] == 3 && iv[3] == 4);

    /* Depth range: clamped; integer queries map [0, 1] onto [0, 2^31 - 1]. */
    glGetFloatv(GL_DEPTH_RANGE, fv);
    CHECK(fv[0] == 0 && fv[1] == 1);
    glDepthRangef(0.25f, 2);
    glGetFloatv(GL_DEPTH_RANGE, fv);
    CHECK(fv[0] == 0.25f && fv[1] == 1);
    glGetIntegerv(GL_DEPTH_RANGE, iv);
    CHECK(iv[1] == 0x7FFFFFFF);
    CHECK(iv[0] >= 0x1FFFFFFF - 1 && iv[0] <= 0x20000000);
    glDepthRangex(0x8000, 0);
    glGetFixedv(GL_DEPTH_RANGE, xv);
    CHECK(xv[0] == 0x8000 && xv[1] == 0);
    CHECK_GL(GL_NO_ERROR);

    /* Conversions: booleans of nonzero values are TRUE; floats of integers are exact. */
    glGetBooleanv(GL_DEPTH_FUNC, bv);
    CHECK(bv[0] == GL_TRUE);
    glGetFloatv(GL_SCISSOR_BOX, fv);
    CHECK(fv[0] == 1 && fv[1] == 2 && fv[2] == 3 && fv[3] == 4);
    glGetFixedv(GL_SCISSOR_BOX, xv);
    CHECK(xv[0] == 0x10000 && xv[3] == 0x40000);
    glGetIntegerv(GL_SUBPIXEL_BITS, iv);
    CHECK(iv[0] >= 4);

    /* Unknown names. */
    iv[0] = 12345;
    glGetIntegerv(GL_TRIANGLES, iv);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(iv[0] == 12345);
    glGetFloatv(0xFFFF, fv);
    CHECK_GL(GL_INVALID_ENUM);
    glGetBooleanv(0xFFFF, bv);
    CHECK_GL(GL_INVALID_ENUM);
    glGetFixedv(0xFFFF, xv);
    CHECK_GL(GL_INVALID_ENUM);

    /* Strings. */
    s = (const char *)glGetString(GL_VERSION);
    CHECK(s != NULL && strncmp(s, "OpenGL ES-CM 1.1 ", 17) == 0);
    s = (const char *)glGetString(GL_VENDOR);
    CHECK(s != NULL && s[0] != 0);
    s = (const char *)glGetString(GL_RENDERER);
    CHECK(s != NULL && s[0] != 0);
    s = (const char *)glGetString(GL_EXTENSIONS);
    CHECK(s != NULL && strstr(s, "GL_OES_read_format") != NULL);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glGetString(GL_TRIANGLES) == NULL);
    CHECK_GL(GL_INVALID_ENUM);

    /* One error flag: the first error sticks until read, later ones are dropped. */
    glEnable(GL_TRIANGLES);
    glViewport(0, 0, -1, -1);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK_GL(GL_NO_ERROR);

    glFlush();
    glFinish();
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
