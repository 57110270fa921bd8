/*
 * The matrix stack: glMatrixMode, Load/Mult (f and x), LoadIdentity, Push/Pop with the
 * stack-depth errors, Translate/Scale/Rotate/Frustum/Ortho (f and x) with their errors, and
 * the matrices read back with glGetFloatv. Products of exactly representable values are
 * compared exactly; rotations within 1e-6.
 */
#include <math.h>

#include "common.h"

static GLfloat m[16];

static int matrix_is(GLenum which, const GLfloat want[16], GLfloat tol)
{
    int i;
    glGetFloatv(which, m);
    for (i = 0; i < 16; ++i)
        if (fabsf(m[i] - want[i]) > tol)
            return 0;
    return 1;
}

int main(void)
{
    static const GLfloat identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const GLfloat a[16] = {1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9, 0, 10, 11, 12, 1};
    /* a * translate(1, 2, 3): the last column becomes a applied to (1, 2, 3, 1). */
    static const GLfloat a_t[16] = {1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9, 0, 40, 47, 54, 1};
    static const GLfloat scale[16] = {2, 0, 0, 0, 0, -3, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1};
    static const GLfloat rot_z90[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    /* glFrustum(-1, 1, -1, 1, 1, 3) and glOrtho(0, 4, 0, 2, -1, 1). */
    static const GLfloat frustum[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -1, 0, 0, -3, 0};
    static const GLfloat ortho[16] = {0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};
    GLfixed ax[16], one = 0x10000;
    GLint depth = 0, max_depth = 0, mode = 0, i;

    ct_init(8, 8);

    glGetIntegerv(GL_MATRIX_MODE, &mode);
    CHECK(mode == GL_MODELVIEW);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, identity, 0));
    CHECK(matrix_is(GL_PROJECTION_MATRIX, identity, 0));
    CHECK(matrix_is(GL_TEXTURE_MATRIX, identity, 0));

    glLoadMatrixf(a);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a, 0));
    glTranslatef(1, 2, 3);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a_t, 0));
    for (i = 0; i < 16; ++i)
        ax[i] = (GLfixed)(a[i] * 65536);
    glLoadMatrixx(ax);
    glTranslatex(one, 2 * one, 3 * one);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a_t, 0));

    glLoadIdentity();
    glMultMatrixf(a);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a, 0));
    glLoadIdentity();
    glMultMatrixx(ax);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a, 0));

    glLoadIdentity();
    glScalef(2, -3, 0.5f);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, scale, 0));
    glLoadIdentity();
    glScalex(2 * one, -3 * one, one / 2);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, scale, 0));

    glLoadIdentity();
    glRotatef(90, 0, 0, 2); /* the axis is normalized */
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, rot_z90, 1e-6f));
    glLoadIdentity();
    glRotatex(90 * one, 0, 0, one);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, rot_z90, 1e-6f));

    glMatrixMode(GL_PROJECTION);
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    CHECK(mode == GL_PROJECTION);
    glLoadIdentity();
    glFrustumf(-1, 1, -1, 1, 1, 3);
    CHECK(matrix_is(GL_PROJECTION_MATRIX, frustum, 1e-6f));
    glLoadIdentity();
    glFrustumx(-one, one, -one, one, one, 3 * one);
    CHECK(matrix_is(GL_PROJECTION_MATRIX, frustum, 1e-6f));
    glLoadIdentity();
    glOrthof(0, 4, 0, 2, -1, 1);
    CHECK(matrix_is(GL_PROJECTION_MATRIX, ortho, 0));
    glLoadIdentity();
    glOrthox(0, 4 * one, 0, 2 * one, -one, one);
    CHECK(matrix_is(GL_PROJECTION_MATRIX, ortho, 0));
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, rot_z90, 1e-6f));
    CHECK_GL(GL_NO_ERROR);

    /* Frustum and ortho errors leave the matrix alone. */
    glLoadIdentity();
    glFrustumf(-1, 1, -1, 1, 0, 3);
    CHECK_GL(GL_INVALID_VALUE);
    glFrustumf(-1, 1, -1, 1, 1, -3);
    CHECK_GL(GL_INVALID_VALUE);
    glFrustumf(-1, 1, -1, 1, 2, 2);
    CHECK_GL(GL_INVALID_VALUE);
    glFrustumf(1, 1, -1, 1, 1, 3);
    CHECK_GL(GL_INVALID_VALUE);
    glFrustumf(-1, 1, 2, 2, 1, 3);
    CHECK_GL(GL_INVALID_VALUE);
    glFrustumx(-one, one, -one, one, -one, one);
    CHECK_GL(GL_INVALID_VALUE);
    glOrthof(1, 1, 0, 1, 0, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glOrthof(0, 1, 1, 1, 0, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glOrthof(0, 1, 0, 1, 1, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glOrthox(0, one, 0, one, one, one);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(matrix_is(GL_PROJECTION_MATRIX, identity, 0));

    /* Stacks: push copies the top, pop restores it; depth limits raise overflow and
     * underflow and change nothing. */
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(a);
    glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &max_depth);
    CHECK(max_depth >= 16);
    for (i = 1; i < max_depth; ++i)
        glPushMatrix();
    CHECK_GL(GL_NO_ERROR);
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    CHECK(depth == max_depth);
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a, 0));
    glPushMatrix();
    CHECK_GL(GL_STACK_OVERFLOW);
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    CHECK(depth == max_depth);
    glLoadIdentity();
    for (i = 1; i < max_depth; ++i)
        glPopMatrix();
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a, 0));
    glPopMatrix();
    CHECK_GL(GL_STACK_UNDERFLOW);
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    CHECK(depth == 1);

    glMatrixMode(GL_PROJECTION);
    glGetIntegerv(GL_MAX_PROJECTION_STACK_DEPTH, &max_depth);
    CHECK(max_depth >= 2);
    for (i = 1; i < max_depth; ++i)
        glPushMatrix();
    glPushMatrix();
    CHECK_GL(GL_STACK_OVERFLOW);
    for (i = 1; i < max_depth; ++i)
        glPopMatrix();
    glPopMatrix();
    CHECK_GL(GL_STACK_UNDERFLOW);

    glMatrixMode(GL_TEXTURE);
    glGetIntegerv(GL_MAX_TEXTURE_STACK_DEPTH, &max_depth);
    CHECK(max_depth >= 2);
    glScalef(2, -3, 0.5f);
    CHECK(matrix_is(GL_TEXTURE_MATRIX, scale, 0));
    glPushMatrix();
    glGetIntegerv(GL_TEXTURE_STACK_DEPTH, &depth);
    CHECK(depth == 2);
    glPopMatrix();
    glPopMatrix();
    CHECK_GL(GL_STACK_UNDERFLOW);
    CHECK(matrix_is(GL_TEXTURE_MATRIX, scale, 0));
    CHECK(matrix_is(GL_MODELVIEW_MATRIX, a, 0)); /* each mode has its own stack */

    glMatrixMode(GL_COLOR_BUFFER_BIT);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    CHECK(mode == GL_TEXTURE);
    return ct_done();
}
