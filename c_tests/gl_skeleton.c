/*
 * The walking skeleton: float vertex and color arrays, an orthographic projection, two
 * overlapping quads drawn with GL_TRIANGLES under the depth test, and a smooth-shaded
 * triangle. Flat-colored pixels are exact; interpolated colors are allowed one step, since
 * the specification leaves the rounding of interpolated values to the implementation.
 *
 * ct:softpipe-edges (the line and triangle edges drawn here run through pixel centers,
 * where softpipe settles ties its own way)
 */
#include "common.h"

/* Two triangles covering [x0, x1] x [y0, y1] at eye z = `z`, every vertex colored `rgb`. */
static void quad(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1, GLfloat z, const GLfloat rgb[3])
{
    GLfloat v[18] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y0, z, x1, y1, z, x0, y1, z};
    GLfloat c[24];
    int i;
    for (i = 0; i < 6; ++i) {
        c[4 * i] = rgb[0];
        c[4 * i + 1] = rgb[1];
        c[4 * i + 2] = rgb[2];
        c[4 * i + 3] = 1;
    }
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColorPointer(4, GL_FLOAT, 0, c);
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

int main(void)
{
    static const GLfloat identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const GLfloat red[3] = {1, 0, 0}, green[3] = {0, 1, 0};
    static const GLfloat tri_v[6] = {0, 0, 64, 0, 0, 64};
    static const GLfloat tri_c[12] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1};
    GLfloat x, y;

    ct_init(64, 64);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(identity);
    glClearColor(0, 0, 0, 1);
    glClearDepthf(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    CHECK_GL(GL_NO_ERROR);

    /* Near green first (eye z 0.5, window depth 0.25), then far red (window depth 0.75):
     * the depth test keeps red only where green is absent. */
    quad(16, 16, 48, 48, 0.5f, green);
    quad(8, 8, 40, 40, -0.5f, red);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(4, 4, 0, 0, 0, 255, 0);
    CHECK_PIXEL(10, 10, 255, 0, 0, 255, 0);
    CHECK_PIXEL(39, 10, 255, 0, 0, 255, 0);
    CHECK_PIXEL(16, 16, 0, 255, 0, 255, 0);
    CHECK_PIXEL(20, 20, 0, 255, 0, 255, 0);
    CHECK_PIXEL(47, 47, 0, 255, 0, 255, 0);
    CHECK_PIXEL(48, 48, 0, 0, 0, 255, 0);
    CHECK_PIXEL(40, 10, 0, 0, 0, 255, 0);
    /* Edges: pixel centers at +0.5, so [8, 40) is covered and 40 is not. */
    CHECK_PIXEL(8, 8, 255, 0, 0, 255, 0);
    CHECK_PIXEL(7, 8, 0, 0, 0, 255, 0);
    CHECK_PIXEL(8, 7, 0, 0, 0, 255, 0);
    ct_save("depth");

    /* GL_GREATER: a quad at window depth 0.5 passes only where the stored depth is below
     * 0.5, which is where green (0.25) is. */
    glDepthFunc(GL_GREATER);
    quad(0, 0, 64, 64, 0.0f, red);
    CHECK_PIXEL(4, 4, 0, 0, 0, 255, 0);
    CHECK_PIXEL(10, 10, 255, 0, 0, 255, 0);
    CHECK_PIXEL(44, 44, 255, 0, 0, 255, 0);
    glDepthFunc(GL_LESS);

    /* Smooth shading: color = red (1 - x/64 - y/64) + green x/64 + blue y/64 at the pixel
     * center, in window space since w = 1 everywhere. */
    glDisable(GL_DEPTH_TEST);
    glClear(GL_COLOR_BUFFER_BIT);
    glVertexPointer(2, GL_FLOAT, 0, tri_v);
    glColorPointer(4, GL_FLOAT, 0, tri_c);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    for (y = 0.5f; y < 64; y += 9) {
        for (x = 0.5f; x + y < 64; x += 7) {
            int r = (int)((1 - x / 64 - y / 64) * 255 + 0.5f);
            int g = (int)(x / 64 * 255 + 0.5f);
            int b = (int)(y / 64 * 255 + 0.5f);
            CHECK_PIXEL((int)x, (int)y, r, g, b, 255, 1);
        }
    }
    CHECK_PIXEL(40, 40, 0, 0, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);
    ct_save("smooth");
    return ct_done();
}
