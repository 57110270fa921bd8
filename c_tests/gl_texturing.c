/*
 * Texture sampling through the whole pipeline: NEAREST onto 1:1 quads (pixel-exact, as the
 * rules fix texel centers at (i + 1/2)/N), 1x1, 1xN and Nx1 textures, REPEAT coordinates of
 * 2^10 and negative ones, CLAMP_TO_EDGE and MIRRORED_REPEAT, bilinear midpoints, q near 0
 * and of mixed sign, paletted 4-bit textures of odd texel count, incomplete textures, a
 * texture redefined or deleted while draws that read it are pending, and multitexture.
 */
#include "common.h"

#define W 32
#define H 32

/* Draws the window rectangle [x0, x1) x [y0, y1) with texture coordinates (s0, t0) at the
 * lower left and (s1, t1) at the upper right on unit 0 (and, when `both`, unit 1). */
static void quad_st(float x0, float y0, float x1, float y1, float s0, float t0, float s1,
                    float t1, int both)
{
    GLfloat v[8] = {x0, y0, x1, y0, x0, y1, x1, y1};
    GLfloat st[8] = {s0, t0, s1, t0, s0, t1, s1, t1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    if (both) {
        glClientActiveTexture(GL_TEXTURE1);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, 0, st);
        glClientActiveTexture(GL_TEXTURE0);
    }
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    if (both) {
        glClientActiveTexture(GL_TEXTURE1);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glClientActiveTexture(GL_TEXTURE0);
    }
}

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void tex_rgba(GLsizei w, GLsizei h, const GLubyte *texels, GLenum filter)
{
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
}

static const GLubyte checker4[4 * 4 * 4] = {
    255, 0,   0,   255, 0,   255, 0,   255, 0,   0,   255, 255, 255, 255, 255, 255,
    10,  20,  30,  40,  50,  60,  70,  80,  90,  100, 110, 120, 130, 140, 150, 160,
    1,   2,   3,   4,   5,   6,   7,   8,   9,   10,  11,  12,  13,  14,  15,  16,
    200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215,
};

/* Texel (i, j) of checker4, row j from the bottom. */
static const GLubyte *texel4(int i, int j)
{
    return &checker4[(j * 4 + i) * 4];
}

static void check_texels4(int x0, int y0, int scale)
{
    int i, j;
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            const GLubyte *t = texel4(i, j);
            CHECK_PIXEL(x0 + i * scale, y0 + j * scale, t[0], t[1], t[2], t[3], 0);
        }
}

static void nearest_2x2_and_4x4_map_texel_centers_exactly(void)
{
    clear();
    tex_rgba(4, 4, checker4, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(0, 0, 4, 4, 0, 0, 1, 1, 0);           /* 1:1 */
    quad_st(8, 0, 16, 8, 0, 0, 1, 1, 0);          /* 2:1 magnified */
    check_texels4(0, 0, 1);
    check_texels4(8, 0, 2);
    check_texels4(9, 1, 2);
    CHECK_GL(GL_NO_ERROR);
}

static void repeat_coordinates_of_2_to_the_10_and_negative(void)
{
    clear();
    tex_rgba(4, 4, checker4, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(0, 0, 4, 4, 1024, 1024, 1025, 1025, 0);
    quad_st(4, 4, 8, 8, -3, -7, -2, -6, 0);
    quad_st(8, 8, 12, 12, -1024, 1023, -1023, 1024, 0);
    check_texels4(0, 0, 1);
    check_texels4(4, 4, 1);
    check_texels4(8, 8, 1);
    CHECK_GL(GL_NO_ERROR);
}

static void clamp_and_mirrored_repeat(void)
{
    int i;
    clear();
    tex_rgba(4, 4, checker4, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    /* s from -1 to 3 over 16 pixels: pixels 0..3 left of the texture take column 0. */
    quad_st(0, 0, 16, 1, -1, 0.1f, 3, 0.1f, 0);
    for (i = 0; i < 4; ++i)
        CHECK_PIXEL(i, 0, 255, 0, 0, 255, 0);
    CHECK_PIXEL(15, 0, 255, 255, 255, 255, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT_OES);
    CHECK_GL(GL_NO_ERROR);
    /* s from 1 to 2 over 4 pixels: mirrored, columns 3, 2, 1, 0. */
    quad_st(0, 2, 4, 3, 1, 0.1f, 2, 0.1f, 0);
    for (i = 0; i < 4; ++i) {
        const GLubyte *t = texel4(3 - i, 0);
        CHECK_PIXEL(i, 2, t[0], t[1], t[2], t[3], 0);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

static void one_by_one_one_by_n_and_n_by_one_textures(void)
{
    static const GLubyte one[4] = {12, 34, 56, 78};
    static const GLubyte row[8 * 4] = {0,  0,  0,  255, 10, 0, 0, 255, 20, 0, 0, 255,
                                       30, 0,  0,  255, 40, 0, 0, 255, 50, 0, 0, 255,
                                       60, 0,  0,  255, 70, 0, 0, 255};
    int i;
    clear();
    tex_rgba(1, 1, one, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(0, 0, 8, 8, -3.3f, 0.7f, 5.1f, 9.9f, 0);
    CHECK_PIXEL(0, 0, 12, 34, 56, 78, 0);
    CHECK_PIXEL(7, 7, 12, 34, 56, 78, 0);
    /* 8 x 1 across, 1 x 8 up: NEAREST picks one texel per pixel. */
    tex_rgba(8, 1, row, GL_NEAREST);
    quad_st(0, 10, 8, 12, 0, 0, 1, 1, 0);
    tex_rgba(1, 8, row, GL_NEAREST);
    quad_st(10, 0, 12, 8, 0, 0, 1, 1, 0);
    for (i = 0; i < 8; ++i) {
        CHECK_PIXEL(i, 11, i * 10, 0, 0, 255, 0);
        CHECK_PIXEL(11, i, i * 10, 0, 0, 255, 0);
    }
    /* LINEAR on 8 x 1 halfway between texel centers: the mean. */
    tex_rgba(8, 1, row, GL_LINEAR);
    quad_st(0, 14, 1, 15, 3.5f / 8, 0, 4.5f / 8, 1, 0);
    CHECK_PIXEL(0, 14, 35, 0, 0, 255, 1);
    CHECK_GL(GL_NO_ERROR);
}

static void modulate_replace_with_exact_colors(void)
{
    static const GLubyte t[4] = {102, 204, 51, 255}; /* 0.4, 0.8, 0.2, 1 */
    clear();
    tex_rgba(1, 1, t, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.5f, 0.25f, 1.0f, 0.2f);
    quad_st(0, 0, 4, 4, 0, 0, 1, 1, 0);
    CHECK_PIXEL(1, 1, 51, 51, 51, 51, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(4, 0, 8, 4, 0, 0, 1, 1, 0);
    CHECK_PIXEL(5, 1, 102, 204, 51, 255, 0);
    glColor4f(1, 1, 1, 1);
}

static void incomplete_texture_disables_its_unit(void)
{
    static const GLubyte t[4] = {0, 255, 0, 255};
    clear();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    /* 2 x 2 without level 1 and a mipmap filter: incomplete, the fragment color stays. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glColor4f(1, 0, 1, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(0, 0, 4, 4, 0, 0, 1, 1, 0);
    CHECK_PIXEL(1, 1, 255, 0, 255, 255, 0);
    glColor4f(1, 1, 1, 1);
}

static void texture_redefined_or_deleted_while_draws_are_pending(void)
{
    static const GLubyte red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255},
                         blue[4] = {0, 0, 255, 255};
    GLuint name = 0;
    clear();
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    tex_rgba(1, 1, red, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(0, 0, 4, 4, 0, 0, 1, 1, 0);
    /* Redefined, then changed in place, before anything is flushed. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
    quad_st(4, 0, 8, 4, 0, 0, 1, 1, 0);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, blue);
    quad_st(8, 0, 12, 4, 0, 0, 1, 1, 0);
    glDeleteTextures(1, &name);
    CHECK_PIXEL(1, 1, 255, 0, 0, 255, 0);
    CHECK_PIXEL(5, 1, 0, 255, 0, 255, 0);
    CHECK_PIXEL(9, 1, 0, 0, 255, 255, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

static void q_near_zero_and_of_mixed_sign(void)
{
    /* Coordinates given as (s, t, 0, q): q crosses 0 inside the quad. Only the absence of
     * faults and of errors is fixed; pixels where q is clearly positive sample normally. */
    static const GLubyte t[4] = {10, 20, 30, 255};
    GLfloat v[8] = {0, 0, 16, 0, 0, 16, 16, 16};
    GLfloat stq[16] = {0.5f, 0.5f, 0, -1, 0.5f, 0.5f, 0, 1e-30f,
                       0.5f, 0.5f, 0, 1,  0.5f, 0.5f, 0, 1e-7f};
    clear();
    tex_rgba(1, 1, t, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(4, GL_FLOAT, 0, stq);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    CHECK_GL(GL_NO_ERROR);
    /* A 1 x 1 texture under REPEAT: every finite coordinate gives its texel. */
    CHECK_PIXEL(1, 15, 10, 20, 30, 255, 0);
}

static void paletted_4_bit_textures_of_odd_texel_count(void)
{
    /* 1 x 1 (one nibble, high) and the 2 x 1 + 1 x 1 chain (three texels). */
    GLubyte blob[16 * 3 + 1];
    GLubyte chain[16 * 3 + 1 + 1];
    memset(blob, 0, sizeof blob);
    blob[5 * 3 + 0] = 77;
    blob[5 * 3 + 1] = 88;
    blob[5 * 3 + 2] = 99;
    blob[48] = 0x50;
    clear();
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGB8_OES, 1, 1, 0, sizeof blob, blob);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad_st(0, 0, 4, 4, 0, 0, 1, 1, 0);
    CHECK_PIXEL(1, 1, 77, 88, 99, 255, 0);
    memcpy(chain, blob, 48);
    chain[3 * 3 + 0] = 1;
    chain[3 * 3 + 1] = 2;
    chain[3 * 3 + 2] = 3;
    chain[48] = 0x53; /* level 0: texels 5, 3 */
    chain[49] = 0x30; /* level 1: texel 3 */
    glCompressedTexImage2D(GL_TEXTURE_2D, -1, GL_PALETTE4_RGB8_OES, 2, 1, 0, sizeof chain, chain);
    CHECK_GL(GL_NO_ERROR);
    quad_st(4, 0, 6, 1, 0, 0, 1, 1, 0);
    CHECK_PIXEL(4, 0, 77, 88, 99, 255, 0);
    CHECK_PIXEL(5, 0, 1, 2, 3, 255, 0);
    /* Minified far enough to read level 1 (NEAREST_MIPMAP_NEAREST). */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    quad_st(8, 0, 9, 1, 0, 0, 4, 4, 0);
    CHECK_PIXEL(8, 0, 1, 2, 3, 255, 0);
}

static void two_units_modulate(void)
{
    static const GLubyte a[4] = {255, 128, 0, 255}, b[4] = {102, 255, 255, 255};
    GLuint names[2];
    clear();
    glGenTextures(2, names);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    tex_rgba(1, 1, a, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, names[1]);
    tex_rgba(1, 1, b, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    quad_st(0, 0, 4, 4, 0, 0, 1, 1, 1);
    CHECK_PIXEL(1, 1, 102, 128, 0, 255, 0);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glDeleteTextures(2, names);
}

int main(void)
{
    ct_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_TEXTURE_2D);
    glDisable(GL_DITHER);

    nearest_2x2_and_4x4_map_texel_centers_exactly();
    ct_save("nearest");
    repeat_coordinates_of_2_to_the_10_and_negative();
    clamp_and_mirrored_repeat();
    one_by_one_one_by_n_and_n_by_one_textures();
    ct_save("sizes");
    modulate_replace_with_exact_colors();
    incomplete_texture_disables_its_unit();
    texture_redefined_or_deleted_while_draws_are_pending();
    q_near_zero_and_of_mixed_sign();
    paletted_4_bit_textures_of_odd_texel_count();
    two_units_modulate();
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
