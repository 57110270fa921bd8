/*
 * Vertex and color arrays and the draw calls: every allowed vertex type (byte, short, fixed,
 * float) and color type (unsigned byte, fixed, float) gives the same exact pixels; strides
 * and interleaving; glDrawArrays and glDrawElements (unsigned byte and short) with the
 * triangle modes pixel-checked and the line and point modes accepted; the current color
 * (f, x, ub); client state queries; and every error of these calls.
 *
 * ct:softpipe-edges (the line and triangle edges drawn here run through pixel centers,
 * where softpipe settles ties its own way)
 */
#include "common.h"

static void setup_view(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, 32, 0, 32, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* The square [8, 24)^2 is white, the pixels around it untouched. */
static void check_square(void)
{
    CHECK_PIXEL(8, 8, 255, 255, 255, 255, 0);
    CHECK_PIXEL(23, 23, 255, 255, 255, 255, 0);
    CHECK_PIXEL(16, 12, 255, 255, 255, 255, 0);
    CHECK_PIXEL(7, 8, 0, 0, 0, 0, 0);
    CHECK_PIXEL(24, 23, 0, 0, 0, 0, 0);
    CHECK_PIXEL(8, 24, 0, 0, 0, 0, 0);
    CHECK_PIXEL(23, 7, 0, 0, 0, 0, 0);
}

int main(void)
{
    /* The square as a triangle strip, in every vertex type. */
    static const GLbyte vb[8] = {8, 8, 24, 8, 8, 24, 24, 24};
    static const GLshort vs[12] = {8, 8, 0, 24, 8, 0, 8, 24, 0, 24, 24, 0};
    static const GLfixed vx[16] = {8 << 16, 8 << 16, 0, 1 << 16, 24 << 16, 8 << 16, 0, 1 << 16,
                                   8 << 16, 24 << 16, 0, 1 << 16, 24 << 16, 24 << 16, 0, 1 << 16};
    static const GLfloat vf[8] = {8, 8, 24, 8, 8, 24, 24, 24};
    static const GLubyte cu[16] = {255, 255, 255, 255, 255, 255, 255, 255,
                                   255, 255, 255, 255, 255, 255, 255, 255};
    static const GLfixed cx[16] = {0x10000, 0x10000, 0x10000, 0x10000, 0x10000, 0x10000,
                                   0x10000, 0x10000, 0x10000, 0x10000, 0x10000, 0x10000,
                                   0x10000, 0x10000, 0x10000, 0x10000};
    /* Fan and triangle-list orders of the same square, and indices. */
    static const GLfloat fan[8] = {8, 8, 24, 8, 24, 24, 8, 24};
    static const GLfloat list[12] = {8, 8, 24, 8, 24, 24, 8, 8, 24, 24, 8, 24};
    static const GLubyte idx_b[6] = {0, 1, 2, 0, 2, 3};
    static const GLushort idx_s[4] = {0, 1, 3, 2};
    /* Interleaved: x, y as floats, then RGBA bytes, then 4 bytes of padding: stride 16. */
    struct vertex {
        GLfloat x, y;
        GLubyte rgba[4];
        GLubyte pad[4];
    } inter[4] = {{8, 8, {255, 255, 255, 255}, {0, 0, 0, 0}},
                  {24, 8, {255, 255, 255, 255}, {0, 0, 0, 0}},
                  {8, 24, {255, 255, 255, 255}, {0, 0, 0, 0}},
                  {24, 24, {255, 255, 255, 255}, {0, 0, 0, 0}}};
    GLint iv[4];
    GLfloat fv[4];
    GLubyte dummy[64];
    GLenum mode;

    ct_init(32, 32);
    setup_view();

    /* Initial client state. */
    CHECK(!glIsEnabled(GL_VERTEX_ARRAY) && !glIsEnabled(GL_COLOR_ARRAY));
    glGetIntegerv(GL_VERTEX_ARRAY_SIZE, iv);
    CHECK(iv[0] == 4);
    glGetIntegerv(GL_VERTEX_ARRAY_TYPE, iv);
    CHECK(iv[0] == GL_FLOAT);
    glGetIntegerv(GL_VERTEX_ARRAY_STRIDE, iv);
    CHECK(iv[0] == 0);
    glGetIntegerv(GL_COLOR_ARRAY_SIZE, iv);
    CHECK(iv[0] == 4);
    glGetIntegerv(GL_COLOR_ARRAY_TYPE, iv);
    CHECK(iv[0] == GL_FLOAT);
    glGetFloatv(GL_CURRENT_COLOR, fv);
    CHECK(fv[0] == 1 && fv[1] == 1 && fv[2] == 1 && fv[3] == 1);

    /* Without the vertex array enabled nothing is drawn, and that is no error. */
    glVertexPointer(2, GL_FLOAT, 0, vf);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(16, 16, 0, 0, 0, 0, 0);

    glEnableClientState(GL_VERTEX_ARRAY);
    CHECK(glIsEnabled(GL_VERTEX_ARRAY));
    glColor4f(1, 1, 1, 1);

    glVertexPointer(2, GL_BYTE, 0, vb);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square();
    setup_view();
    glVertexPointer(3, GL_SHORT, 0, vs);
    glGetIntegerv(GL_VERTEX_ARRAY_SIZE, iv);
    CHECK(iv[0] == 3);
    glGetIntegerv(GL_VERTEX_ARRAY_TYPE, iv);
    CHECK(iv[0] == GL_SHORT);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square();
    setup_view();
    glVertexPointer(4, GL_FIXED, 0, vx);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square();
    CHECK_GL(GL_NO_ERROR);

    /* Color arrays of every type, the current color set to black so it would show. */
    glColor4ub(0, 0, 0, 0);
    glEnableClientState(GL_COLOR_ARRAY);
    setup_view();
    glVertexPointer(2, GL_FLOAT, 0, vf);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, cu);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square();
    setup_view();
    glColorPointer(4, GL_FIXED, 0, cx);
    glGetIntegerv(GL_COLOR_ARRAY_TYPE, iv);
    CHECK(iv[0] == GL_FIXED);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square();

    /* Interleaved with a stride; the colors start 8 bytes into each vertex. */
    setup_view();
    glVertexPointer(2, GL_FLOAT, sizeof(struct vertex), &inter[0].x);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vertex), inter[0].rgba);
    glGetIntegerv(GL_VERTEX_ARRAY_STRIDE, iv);
    CHECK(iv[0] == (GLint)sizeof(struct vertex));
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square();
    glDisableClientState(GL_COLOR_ARRAY);
    CHECK(!glIsEnabled(GL_COLOR_ARRAY));

    /* The other modes and the index types. */
    glColor4x(0x10000, 0x10000, 0x10000, 0x10000);
    setup_view();
    glVertexPointer(2, GL_FLOAT, 0, fan);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    check_square();
    setup_view();
    glVertexPointer(2, GL_FLOAT, 0, list);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    check_square();
    setup_view();
    glVertexPointer(2, GL_FLOAT, 0, fan);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx_b);
    check_square();
    setup_view();
    glDrawElements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_SHORT, idx_s);
    check_square();
    /* `first` offsets into the arrays: the second triangle of the list alone. */
    setup_view();
    glVertexPointer(2, GL_FLOAT, 0, list);
    glDrawArrays(GL_TRIANGLES, 3, 3);
    CHECK_PIXEL(9, 20, 255, 255, 255, 255, 0);
    CHECK_PIXEL(20, 9, 0, 0, 0, 0, 0);
    /* Incomplete primitives draw nothing. */
    setup_view();
    glDrawArrays(GL_TRIANGLES, 0, 2);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 2);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 0);
    CHECK_PIXEL(16, 16, 0, 0, 0, 0, 0);
    for (mode = GL_POINTS; mode <= GL_TRIANGLE_FAN; ++mode) {
        glDrawArrays(mode, 0, 4);
        glDrawElements(mode, 4, GL_UNSIGNED_SHORT, idx_s);
    }
    CHECK_GL(GL_NO_ERROR);
    ct_save("square");

    /* Current color, in each form. */
    glColor4ub(255, 51, 0, 102);
    glGetFloatv(GL_CURRENT_COLOR, fv);
    CHECK(fv[0] == 1 && fv[1] == 0.2f && fv[2] == 0 && fv[3] == 0.4f);
    glColor4x(0x8000, 0, 0x10000, 0x4000);
    glGetFloatv(GL_CURRENT_COLOR, fv);
    CHECK(fv[0] == 0.5f && fv[1] == 0 && fv[2] == 1 && fv[3] == 0.25f);
    glColor4f(0.75f, 0.5f, 0.25f, 1);
    glGetFloatv(GL_CURRENT_COLOR, fv);
    CHECK(fv[0] == 0.75f && fv[1] == 0.5f && fv[2] == 0.25f && fv[3] == 1);
    glGetIntegerv(GL_CURRENT_COLOR, iv);
    CHECK(iv[3] == 0x7FFFFFFF);

    /* Errors. Each leaves the array state as it was. */
    glVertexPointer(2, GL_FLOAT, 0, vf);
    glVertexPointer(1, GL_FLOAT, 0, dummy);
    CHECK_GL(GL_INVALID_VALUE);
    glVertexPointer(5, GL_FLOAT, 0, dummy);
    CHECK_GL(GL_INVALID_VALUE);
    glVertexPointer(2, GL_FLOAT, -4, dummy);
    CHECK_GL(GL_INVALID_VALUE);
    glVertexPointer(2, GL_UNSIGNED_BYTE, 0, dummy);
    CHECK_GL(GL_INVALID_ENUM);
    glVertexPointer(2, 0x1404 /* GL_INT: desktop GL only */, 0, dummy);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_VERTEX_ARRAY_SIZE, iv);
    CHECK(iv[0] == 2);
    glGetIntegerv(GL_VERTEX_ARRAY_TYPE, iv);
    CHECK(iv[0] == GL_FLOAT);
    glColorPointer(3, GL_FLOAT, 0, dummy);
    CHECK_GL(GL_INVALID_VALUE);
    glColorPointer(4, GL_FLOAT, -1, dummy);
    CHECK_GL(GL_INVALID_VALUE);
    glColorPointer(4, GL_BYTE, 0, dummy);
    CHECK_GL(GL_INVALID_ENUM);
    glColorPointer(4, GL_SHORT, 0, dummy);
    CHECK_GL(GL_INVALID_ENUM);
    glEnableClientState(GL_TEXTURE_2D);
    CHECK_GL(GL_INVALID_ENUM);
    glDisableClientState(GL_LIGHTING);
    CHECK_GL(GL_INVALID_ENUM);

    glDrawArrays(GL_TRIANGLE_FAN + 1, 0, 3);
    CHECK_GL(GL_INVALID_ENUM);
    glDrawArrays(GL_TRIANGLES, 0, -1);
    CHECK_GL(GL_INVALID_VALUE);
    glDrawElements(GL_TRIANGLE_FAN + 1, 3, GL_UNSIGNED_BYTE, idx_b);
    CHECK_GL(GL_INVALID_ENUM);
    glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_BYTE, idx_b);
    CHECK_GL(GL_INVALID_VALUE);
    glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, idx_b);
    CHECK_GL(GL_INVALID_ENUM);
    glDrawElements(GL_TRIANGLES, 3, GL_BYTE, idx_b);
    CHECK_GL(GL_INVALID_ENUM);
    return ct_done();
}
