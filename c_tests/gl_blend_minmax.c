/*
 * gl_blend_minmax.c: GL_EXT_blend_minmax: GL_MIN_EXT and GL_MAX_EXT take the smaller or
 * larger of source and destination per channel and ignore the blend factors; they combine
 * with OES_blend_equation_separate (inputs are multiples of 51/255, exact in 8 bits).
 */
#include "common.h"

#ifndef GL_MIN_EXT
#define GL_MIN_EXT 0x8007
#define GL_MAX_EXT 0x8008
#endif

typedef void(GL_APIENTRYP blend_equation_fn)(GLenum);
typedef void(GL_APIENTRYP blend_equation_separate_fn)(GLenum, GLenum);

static void full_quad(GLfloat r, GLfloat g, GLfloat b, GLfloat a)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColor4f(r, g, b, a);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

int main(void)
{
    blend_equation_fn equation;
    blend_equation_separate_fn separate;
    GLint v = 0;

    ct_init(8, 8);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_blend_minmax") != NULL);
    equation = (blend_equation_fn)eglGetProcAddress("glBlendEquationOES");
    separate = (blend_equation_separate_fn)eglGetProcAddress("glBlendEquationSeparateOES");
    CHECK(equation && separate);
    if (!equation || !separate)
        return ct_done();

    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_ZERO); /* factors MIN and MAX must not use */

    glClearColor(0.6f, 0.2f, 0.8f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    equation(GL_MIN_EXT);
    CHECK_GL(GL_NO_ERROR);
    glGetIntegerv(GL_BLEND_EQUATION_OES, &v);
    CHECK(v == GL_MIN_EXT);
    full_quad(0.4f, 0.6f, 1.0f, 0.2f);
    CHECK_PIXEL(4, 4, 102, 51, 204, 51, 0);

    glClear(GL_COLOR_BUFFER_BIT);
    equation(GL_MAX_EXT);
    full_quad(0.4f, 0.6f, 1.0f, 0.2f);
    CHECK_PIXEL(4, 4, 153, 153, 255, 102, 0);

    /* Separate: MIN for color, MAX for alpha. */
    glClear(GL_COLOR_BUFFER_BIT);
    separate(GL_MIN_EXT, GL_MAX_EXT);
    full_quad(0.4f, 0.6f, 1.0f, 0.2f);
    CHECK_PIXEL(4, 4, 102, 51, 204, 102, 0);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA_OES, &v);
    CHECK(v == GL_MAX_EXT);
    CHECK_GL(GL_NO_ERROR);

    equation(GL_MIN_EXT + 2);
    CHECK_GL(GL_INVALID_ENUM);
    return ct_done();
}
