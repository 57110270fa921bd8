/*
 * OES_draw_texture: glDrawTex{s,i,x,f}[v]OES draw window-aligned rectangles sampled through
 * each enabled unit's crop rectangle. NEAREST at 1:1 and 2:1 is pixel-exact (texel centers
 * fall inside pixels), as are crop sub-rectangles, a flipped crop (negative height), the
 * window depth z mapped through the depth range, the current color without a texture, the
 * texture matrix and viewport being ignored (and applying again to the draws after), two
 * units with their own crops, and every entry point. Errors: width or height <= 0.
 */
#include "common.h"

/* Extension functions through eglGetProcAddress (Mesa exports them only that way). */
static PFNGLDRAWTEXSOESPROC glDrawTexsOES;
static PFNGLDRAWTEXIOESPROC glDrawTexiOES;
static PFNGLDRAWTEXXOESPROC glDrawTexxOES;
static PFNGLDRAWTEXFOESPROC glDrawTexfOES;
static PFNGLDRAWTEXSVOESPROC glDrawTexsvOES;
static PFNGLDRAWTEXIVOESPROC glDrawTexivOES;
static PFNGLDRAWTEXXVOESPROC glDrawTexxvOES;
static PFNGLDRAWTEXFVOESPROC glDrawTexfvOES;

static void load(void)
{
    glDrawTexsOES = (PFNGLDRAWTEXSOESPROC)eglGetProcAddress("glDrawTexsOES");
    glDrawTexiOES = (PFNGLDRAWTEXIOESPROC)eglGetProcAddress("glDrawTexiOES");
    glDrawTexxOES = (PFNGLDRAWTEXXOESPROC)eglGetProcAddress("glDrawTexxOES");
    glDrawTexfOES = (PFNGLDRAWTEXFOESPROC)eglGetProcAddress("glDrawTexfOES");
    glDrawTexsvOES = (PFNGLDRAWTEXSVOESPROC)eglGetProcAddress("glDrawTexsvOES");
    glDrawTexivOES = (PFNGLDRAWTEXIVOESPROC)eglGetProcAddress("glDrawTexivOES");
    glDrawTexxvOES = (PFNGLDRAWTEXXVOESPROC)eglGetProcAddress("glDrawTexxvOES");
    glDrawTexfvOES = (PFNGLDRAWTEXFVOESPROC)eglGetProcAddress("glDrawTexfvOES");
}

#define W 64
#define H 64
#define T 8

static GLubyte tex[T * T * 4];

/* Texel (i, j) of the test texture, row j from the bottom. */
static const GLubyte *texel(int i, int j)
{
    return &tex[(j * T + i) * 4];
}

static void make_texture(void)
{
    int i, j;
    for (j = 0; j < T; ++j)
        for (i = 0; i < T; ++i) {
            GLubyte *t = &tex[(j * T + i) * 4];
            t[0] = (GLubyte)(i * 32 + 8);
            t[1] = (GLubyte)(j * 32 + 8);
            t[2] = (GLubyte)(((i ^ j) & 7) * 30);
            t[3] = 255;
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

/* Whether pixel (x, y) is (r, g, b, a) within tol, for checks Mesa departs from. */
static int pixel_is(int x, int y, int r, int g, int b, int a, int tol)
{
    GLubyte p[4];
    ct_read(x, y, p);
    return ct_near(p[0], r, tol) && ct_near(p[1], g, tol) && ct_near(p[2], b, tol) &&
           ct_near(p[3], a, tol);
}

#define STALE_COLOR "Mesa 22 draws with a stale current color (white) after glColor4f"

static void crop(GLint u, GLint v, GLint w, GLint h)
{
    GLint r[4];
    r[0] = u;
    r[1] = v;
    r[2] = w;
    r[3] = h;
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, r);
}

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClearDepthf(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void one_to_one_and_two_to_one(void)
{
    int i, j;
    clear();
    crop(0, 0, T, T);
    glDrawTexiOES(4, 4, 0, T, T);
    glDrawTexfOES(20, 4, 0, 2 * T, 2 * T);
    CHECK_GL(GL_NO_ERROR);
    for (j = 0; j < T; ++j)
        for (i = 0; i < T; ++i) {
            const GLubyte *t = texel(i, j);
            CHECK_PIXEL(4 + i, 4 + j, t[0], t[1], t[2], t[3], 0);
            CHECK_PIXEL(20 + 2 * i, 4 + 2 * j, t[0], t[1], t[2], t[3], 0);
            CHECK_PIXEL(21 + 2 * i, 5 + 2 * j, t[0], t[1], t[2], t[3], 0);
        }
    /* Nothing outside the rectangles. */
    CHECK_PIXEL(3, 4, 0, 0, 0, 0, 0);
    CHECK_PIXEL(4 + T, 4, 0, 0, 0, 0, 0);
    CHECK_PIXEL(4, 4 + T, 0, 0, 0, 0, 0);
    CHECK_PIXEL(20 + 2 * T, 4, 0, 0, 0, 0, 0);
    ct_save("scales");
}

static void crop_sub_rectangles(void)
{
    int i, j;
    clear();
    /* Texels (2..5, 3..6) at 1:1. */
    crop(2, 3, 4, 4);
    glDrawTexsOES(40, 4, 0, 4, 4);
    /* The whole texture upside down: a negative crop height runs t downwards. */
    crop(0, T, T, -T);
    glDrawTexiOES(4, 20, 0, T, T);
    /* Texels (4..7, 0..1) at 2:1 horizontally and 4:1 vertically. */
    crop(4, 0, 4, 2);
    glDrawTexiOES(40, 20, 0, 8, 8);
    CHECK_GL(GL_NO_ERROR);
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            const GLubyte *t = texel(2 + i, 3 + j);
            CHECK_PIXEL(40 + i, 4 + j, t[0], t[1], t[2], t[3], 0);
        }
    for (j = 0; j < T; ++j)
        for (i = 0; i < T; ++i) {
            const GLubyte *t = texel(i, T - 1 - j);
            CHECK_PIXEL(4 + i, 20 + j, t[0], t[1], t[2], t[3], 0);
        }
    for (j = 0; j < 8; ++j)
        for (i = 0; i < 8; ++i) {
            const GLubyte *t = texel(4 + i / 2, j / 4);
            CHECK_PIXEL(40 + i, 20 + j, t[0], t[1], t[2], t[3], 0);
        }
    ct_save("crops");
    crop(0, 0, T, T);
}

static void depth_and_ignored_state(void)
{
    const GLubyte *t = texel(0, 0);
    clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    crop(0, 0, 1, 1);
    /* z = 1 is the far plane: not less than the cleared depth 1. */
    glDrawTexfOES(0, 0, 1.0f, 8, 8);
    CHECK_PIXEL(2, 2, 0, 0, 0, 0, 0);
    /* z = 0.5 passes and writes depth 0.5; then 0.75 fails and 0.25 passes. */
    glDrawTexfOES(0, 0, 0.5f, 8, 8);
    CHECK_PIXEL(2, 2, t[0], t[1], t[2], t[3], 0);
    glDisable(GL_TEXTURE_2D);
    glColor4f(1, 0, 1, 1);
    glDrawTexfOES(0, 0, 0.75f, 8, 8);
    CHECK_PIXEL(2, 2, t[0], t[1], t[2], t[3], 0);
    glDrawTexfOES(0, 0, 0.25f, 4, 4);
    /* Untextured: the current color. */
    CHECK_MESA_DEVIATES(pixel_is(2, 2, 255, 0, 255, 255, 0), STALE_COLOR);
    CHECK_PIXEL(6, 6, t[0], t[1], t[2], t[3], 0);
    /* The depth range maps z: with [0.5, 1], z = 0 lands at 0.5, not below 0.25. */
    glDepthRangef(0.5f, 1.0f);
    glColor4f(0, 1, 0, 1);
    glDrawTexfOES(0, 0, 0.0f, 4, 4);
    CHECK_MESA_DEVIATES(pixel_is(2, 2, 255, 0, 255, 255, 0), STALE_COLOR);
    glDepthRangef(0, 1);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_TEXTURE_2D);
    glColor4f(1, 1, 1, 1);

    /* Neither the texture matrix nor the viewport applies. */
    crop(0, 0, T, T);
    glMatrixMode(GL_TEXTURE);
    glScalef(0.5f, 0.25f, 1);
    glMatrixMode(GL_MODELVIEW);
    glViewport(0, 0, 1, 1);
    glDrawTexiOES(30, 30, 0, T, T);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    t = texel(7, 5);
    CHECK_PIXEL(37, 35, t[0], t[1], t[2], t[3], 0);
    /* A rectangle partly outside the surface keeps its mapping. */
    glDrawTexiOES(-4, 50, 0, T, T);
    t = texel(4, 2);
    CHECK_PIXEL(0, 52, t[0], t[1], t[2], t[3], 0);
    CHECK_GL(GL_NO_ERROR);
    ct_save("depth");
}

/* A draw after glDrawTexOES takes the state the rectangle ignored: the texture matrix and
 * the viewport apply to it again. */
static void draws_after_keep_the_ignored_state(void)
{
    static const GLfloat pos[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    static const GLfloat tc[] = {0, 0, 1, 0, 1, 1, 0, 1};
    const GLubyte *t;
    int i, j;
    clear();
    crop(0, 0, T, T);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(2.0f / T, 0, 0);
    glMatrixMode(GL_MODELVIEW);
    glViewport(W / 2, H / 2, W / 2, H / 2);
    glDrawTexiOES(0, 0, 0, T, T);
    t = texel(3, 3);
    CHECK_PIXEL(3, 3, t[0], t[1], t[2], t[3], 0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glTexCoordPointer(2, GL_FLOAT, 0, tc);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    /* Four pixels a texel in the upper right quarter, shifted by two texels (REPEAT). */
    for (j = 0; j < T; ++j)
        for (i = 0; i < T; ++i) {
            t = texel((i + 2) % T, j);
            CHECK_PIXEL(W / 2 + 4 * i + 2, H / 2 + 4 * j + 2, t[0], t[1], t[2], t[3], 0);
        }
    CHECK_PIXEL(W / 2 - 1, H / 2 - 1, 0, 0, 0, 0, 0);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    CHECK_GL(GL_NO_ERROR);
    ct_save("draw_after");
}

static void modulate_and_two_units(void)
{
    static const GLubyte gray[4] = {128, 128, 128, 128};
    GLuint names[2];
    const GLubyte *t = texel(3, 1);
    clear();
    glGenTextures(2, names);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    make_texture();
    crop(3, 1, 1, 1);
    /* Unit 1: a 1x1 gray texture modulating the result. */
    glActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, names[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, gray);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    crop(0, 0, 1, 1);
    glActiveTexture(GL_TEXTURE0);
    glDrawTexiOES(10, 10, 0, 4, 4);
    CHECK_PIXEL(11, 11, (t[0] * 128 + 127) / 255, (t[1] * 128 + 127) / 255,
                (t[2] * 128 + 127) / 255, 128, 1);
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    /* MODULATE with the current color on unit 0. */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(1, 0, 1, 1);
    glDrawTexiOES(20, 10, 0, 4, 4);
    CHECK_MESA_DEVIATES(pixel_is(21, 11, t[0], 0, t[2], 255, 1), STALE_COLOR);
    glColor4f(1, 1, 1, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CHECK_GL(GL_NO_ERROR);
    ct_save("units");
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(2, names);
}

static void every_entry_point_and_errors(void)
{
    GLshort sv[5] = {0, 0, 0, 2, 2};
    GLint iv[5] = {4, 0, 0, 2, 2};
    GLfixed xv[5] = {8 << 16, 0, 0, 2 << 16, 2 << 16};
    GLfloat fv[5] = {12, 0, 0, 2, 2};
    const GLubyte *t;
    int k;
    clear();
    crop(5, 6, 1, 1);
    t = texel(5, 6);
    glDrawTexsvOES(sv);
    glDrawTexivOES(iv);
    glDrawTexxvOES(xv);
    glDrawTexfvOES(fv);
    glDrawTexsOES(16, 0, 0, 2, 2);
    glDrawTexiOES(20, 0, 0, 2, 2);
    glDrawTexxOES(24 << 16, 0, 0, 2 << 16, 2 << 16);
    glDrawTexfOES(28, 0, 0, 2, 2);
    CHECK_GL(GL_NO_ERROR);
    for (k = 0; k < 8; ++k) {
        CHECK_PIXEL(4 * k, 0, t[0], t[1], t[2], t[3], 0);
        CHECK_PIXEL(4 * k + 1, 1, t[0], t[1], t[2], t[3], 0);
        CHECK_PIXEL(4 * k + 2, 0, 0, 0, 0, 0, 0);
    }
    /* Width or height <= 0: INVALID_VALUE, nothing drawn. */
    glDrawTexiOES(40, 40, 0, 0, 4);
    CHECK_GL(GL_INVALID_VALUE);
    glDrawTexfOES(40, 40, 0, 4, -1);
    CHECK_GL(GL_INVALID_VALUE);
    sv[3] = 0;
    glDrawTexsvOES(sv);
    CHECK_GL(GL_INVALID_VALUE);
    iv[4] = -2;
    glDrawTexivOES(iv);
    CHECK_GL(GL_INVALID_VALUE);
    xv[3] = -1;
    glDrawTexxvOES(xv);
    CHECK_GL(GL_INVALID_VALUE);
    fv[4] = 0;
    glDrawTexfvOES(fv);
    CHECK_GL(GL_INVALID_VALUE);
    glDrawTexsOES(40, 40, 0, -1, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glDrawTexxOES(40 << 16, 40 << 16, 0, 1 << 16, 0);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK_PIXEL(41, 41, 0, 0, 0, 0, 0);
    ct_save("entry_points");
}

int main(void)
{
    ct_init(W, H);
    load();
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_draw_texture") != NULL);
    glEnable(GL_TEXTURE_2D);
    make_texture();
    one_to_one_and_two_to_one();
    crop_sub_rectangles();
    depth_and_ignored_state();
    draws_after_keep_the_ignored_state();
    modulate_and_two_units();
    glBindTexture(GL_TEXTURE_2D, 0);
    make_texture();
    every_entry_point_and_errors();
    return ct_done();
}
