/*
 * OES_blend_subtract, OES_blend_func_separate, OES_blend_equation_separate and
 * OES_stencil_wrap: equations and separate factors on exact inputs (multiples of 51/255,
 * whose sums and differences are whole steps), their state queries, their errors, and the
 * wrapping stencil operations. The blend functions are fetched with eglGetProcAddress, as
 * an application must when the extension is optional.
 */
#include "common.h"

typedef void(GL_APIENTRYP blend_equation_fn)(GLenum);
typedef void(GL_APIENTRYP blend_equation_separate_fn)(GLenum, GLenum);
typedef void(GL_APIENTRYP blend_func_separate_fn)(GLenum, GLenum, GLenum, GLenum);

static void full_quad(GLfloat r, GLfloat g, GLfloat b, GLfloat a)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColor4f(r, g, b, a);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

static GLint geti(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

int main(void)
{
    blend_equation_fn equation;
    blend_equation_separate_fn equation_separate;
    blend_func_separate_fn func_separate;
    const char *ext;

    ct_init(8, 8);
    ext = (const char *)glGetString(GL_EXTENSIONS);
    if (!ext || !strstr(ext, "GL_OES_blend_subtract") ||
        !strstr(ext, "GL_OES_blend_func_separate") ||
        !strstr(ext, "GL_OES_blend_equation_separate")) {
        /* An implementation without them has nothing to test here. */
        CHECK(!ct_strict());
        return ct_done();
    }
    equation = (blend_equation_fn)eglGetProcAddress("glBlendEquationOES");
    equation_separate =
        (blend_equation_separate_fn)eglGetProcAddress("glBlendEquationSeparateOES");
    func_separate = (blend_func_separate_fn)eglGetProcAddress("glBlendFuncSeparateOES");
    CHECK(equation && equation_separate && func_separate);
    if (!equation || !equation_separate || !func_separate)
        return ct_done();

    /* Defaults. */
    CHECK(geti(GL_BLEND_EQUATION_OES) == GL_FUNC_ADD_OES);
    CHECK(geti(GL_BLEND_EQUATION_ALPHA_OES) == GL_FUNC_ADD_OES);
    CHECK(geti(GL_BLEND_SRC_RGB_OES) == GL_ONE && geti(GL_BLEND_DST_RGB_OES) == GL_ZERO);
    CHECK(geti(GL_BLEND_SRC_ALPHA_OES) == GL_ONE && geti(GL_BLEND_DST_ALPHA_OES) == GL_ZERO);

    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);

    /* Subtract: 204 - 51 = 153 in every channel. */
    glClearColor(0.2f, 0.2f, 0.2f, 0.2f);
    glClear(GL_COLOR_BUFFER_BIT);
    equation(GL_FUNC_SUBTRACT_OES);
    CHECK(geti(GL_BLEND_EQUATION_OES) == GL_FUNC_SUBTRACT_OES);
    full_quad(0.8f, 0.8f, 0.8f, 0.8f);
    CHECK_PIXEL(3, 3, 153, 153, 153, 153, 0);

    /* Reverse subtract: destination 153 minus source 51 = 102; a negative result clamps. */
    equation(GL_FUNC_REVERSE_SUBTRACT_OES);
    full_quad(0.2f, 1.0f, 0.2f, 0.2f);
    CHECK_PIXEL(3, 3, 102, 0, 102, 102, 0);

    /* Separate equations: color adds, alpha reverse-subtracts. */
    equation_separate(GL_FUNC_ADD_OES, GL_FUNC_REVERSE_SUBTRACT_OES);
    CHECK(geti(GL_BLEND_EQUATION_RGB_OES) == GL_FUNC_ADD_OES);
    CHECK(geti(GL_BLEND_EQUATION_ALPHA_OES) == GL_FUNC_REVERSE_SUBTRACT_OES);
    full_quad(0.2f, 0.2f, 0.2f, 0.2f);
    CHECK_PIXEL(3, 3, 153, 51, 153, 51, 0);

    /* Separate factors: color replaces, alpha keeps the destination. */
    equation(GL_FUNC_ADD_OES);
    func_separate(GL_ONE, GL_ZERO, GL_ZERO, GL_ONE);
    CHECK(geti(GL_BLEND_SRC_RGB_OES) == GL_ONE && geti(GL_BLEND_DST_RGB_OES) == GL_ZERO);
    CHECK(geti(GL_BLEND_SRC_ALPHA_OES) == GL_ZERO && geti(GL_BLEND_DST_ALPHA_OES) == GL_ONE);
    full_quad(1.0f, 0.6f, 0.0f, 1.0f);
    CHECK_PIXEL(3, 3, 255, 153, 0, 51, 0);
    /* glBlendFunc sets both pairs again. */
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    CHECK(geti(GL_BLEND_SRC_ALPHA_OES) == GL_SRC_ALPHA);
    CHECK(geti(GL_BLEND_DST_ALPHA_OES) == GL_ONE_MINUS_SRC_ALPHA);
    CHECK_GL(GL_NO_ERROR);

    /* Errors leave the state alone. */
    equation(GL_ZERO);
    CHECK_GL(GL_INVALID_ENUM);
    equation_separate(GL_FUNC_ADD_OES, GL_TEXTURE_2D);
    CHECK_GL(GL_INVALID_ENUM);
    func_separate(GL_TEXTURE_2D, GL_ZERO, GL_ONE, GL_ZERO);
    CHECK_GL(GL_INVALID_ENUM);
    func_separate(GL_ONE, GL_ZERO, GL_ONE, GL_TEXTURE_2D);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_BLEND_EQUATION_OES) == GL_FUNC_ADD_OES);
    CHECK(geti(GL_BLEND_SRC_RGB_OES) == GL_SRC_ALPHA);
    glDisable(GL_BLEND);
    ct_save("blend");

    /* OES_stencil_wrap: INCR_WRAP takes 255 to 0, DECR_WRAP takes 0 to 255. */
    if (strstr(ext, "GL_OES_stencil_wrap")) {
        glEnable(GL_STENCIL_TEST);
        glClearStencil(255);
        glClear(GL_STENCIL_BUFFER_BIT);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP_OES);
        CHECK(geti(GL_STENCIL_PASS_DEPTH_PASS) == GL_INCR_WRAP_OES);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        full_quad(0, 0, 0, 1);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glStencilFunc(GL_EQUAL, 0, 0xFF);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        full_quad(0, 1, 0, 1);
        CHECK_PIXEL(3, 3, 0, 255, 0, 255, 0);

        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP_OES);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        full_quad(0, 0, 0, 1);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glStencilFunc(GL_EQUAL, 255, 0xFF);
        glClear(GL_COLOR_BUFFER_BIT);
        full_quad(0, 0, 1, 1);
        CHECK_PIXEL(3, 3, 0, 0, 255, 255, 0);
        glDisable(GL_STENCIL_TEST);
        CHECK_GL(GL_NO_ERROR);
    } else {
        CHECK(!ct_strict());
    }
    return ct_done();
}
