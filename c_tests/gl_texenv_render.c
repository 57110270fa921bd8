/*
 * Texture environments, fog, generated mipmaps and point sprites as they reach pixels:
 * DECAL, BLEND, ADD and COMBINE (ADD_SIGNED, INTERPOLATE, DOT3_RGB, scales) with colors
 * chosen so the results are exact; LINEAR fog at a known eye depth; GENERATE_MIPMAP toggled
 * between uploads (a level generated earlier stays until the flag regenerates it); point
 * sprite coordinates with (0, 0) at the upper left.
 */
#include "common.h"

#define W 32
#define H 32

static void quad_z(float x0, float y0, float x1, float y1, float z, float s1, float t1)
{
    GLfloat v[12] = {x0, y0, z, x1, y0, z, x0, y1, z, x1, y1, z};
    GLfloat st[8] = {0, 0, s1, 0, 0, t1, s1, t1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void tex1(GLenum format, const GLubyte *texel)
{
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, format, 1, 1, 0, format, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static void basic_modes_with_exact_colors(void)
{
    static const GLubyte rgba[4] = {255, 0, 102, 51}; /* 1, 0, 0.4, 0.2 */
    static const GLubyte lum[1] = {51};              /* 0.2 */
    static const GLfloat env[4] = {0.0f, 1.0f, 0.6f, 0.0f};
    glColor4f(0.0f, 0.6f, 1.0f, 1.0f);
    tex1(GL_RGBA, rgba);
    /* DECAL: Cf(1 - As) + Cs As = (0.2, 0.48, 0.88), Af. */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    quad_z(0, 0, 4, 4, 0, 1, 1);
    CHECK_PIXEL(1, 1, 51, 122, 224, 255, 1);
    /* ADD: (1, 0.6, 1) clamped, Af As = 0.2. */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    quad_z(4, 0, 8, 4, 0, 1, 1);
    CHECK_PIXEL(5, 1, 255, 153, 255, 51, 1);
    /* BLEND with a luminance texel: Cf(1 - L) + Cc L = (0, 0.68, 0.92), Af. */
    tex1(GL_LUMINANCE, lum);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    quad_z(8, 0, 12, 4, 0, 1, 1);
    CHECK_PIXEL(9, 1, 0, 173, 235, 255, 1);
    CHECK_GL(GL_NO_ERROR);
}

static void combine_functions(void)
{
    static const GLubyte t[4] = {204, 102, 51, 255}; /* 0.8, 0.4, 0.2, 1 */
    static const GLfloat c[4] = {0.5f, 0.5f, 0.5f, 0.25f};
    tex1(GL_RGBA, t);
    glColor4f(0.2f, 0.4f, 0.6f, 1.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
    /* ADD_SIGNED texture + primary: (0.5, 0.3, 0.3); alpha REPLACE constant 0.25. */
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA, GL_CONSTANT);
    quad_z(0, 8, 4, 12, 0, 1, 1);
    CHECK_PIXEL(1, 9, 128, 77, 77, 64, 1);
    /* Scaled by 2: (1, 0.6, 0.6), alpha by 4: 1. */
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4.0f);
    quad_z(4, 8, 8, 12, 0, 1, 1);
    CHECK_PIXEL(5, 9, 255, 153, 153, 255, 1);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1.0f);
    /* INTERPOLATE texture, primary by constant alpha 0.25: 0.25 T + 0.75 P. */
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC2_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
    quad_z(8, 8, 12, 12, 0, 1, 1);
    CHECK_PIXEL(9, 9, 89, 102, 128, 64, 1);
    /* DOT3_RGB of texture and constant: 4((0.3)(0) + (-0.1)(0) + (-0.3)(0)) = 0. */
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_CONSTANT);
    quad_z(12, 8, 16, 12, 0, 1, 1);
    CHECK_PIXEL(13, 9, 0, 0, 0, 64, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(1, 1, 1, 1);
    CHECK_GL(GL_NO_ERROR);
}

static void linear_fog_at_a_known_depth(void)
{
    static const GLubyte white[4] = {255, 255, 255, 255};
    static const GLfloat blue[4] = {0, 0, 1, 1};
    tex1(GL_RGBA, white);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_FOG);
    glFogf(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 8.0f);
    glFogfv(GL_FOG_COLOR, blue);
    /* Eye z = -6: f = (8 - 6) / 8 = 0.25 of white, 0.75 of blue; alpha untouched. */
    glHint(GL_FOG_HINT, GL_NICEST);
    quad_z(0, 16, 4, 20, -6, 1, 1);
    CHECK_PIXEL(1, 17, 64, 64, 255, 255, 1);
    glHint(GL_FOG_HINT, GL_FASTEST);
    quad_z(4, 16, 8, 20, -6, 1, 1);
    CHECK_PIXEL(5, 17, 64, 64, 255, 255, 1);
    glDisable(GL_FOG);
    glHint(GL_FOG_HINT, GL_DONT_CARE);
    CHECK_GL(GL_NO_ERROR);
}

static void generate_mipmap_toggled_between_uploads(void)
{
    static const GLubyte four[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                     0, 0, 255, 255, 255, 255, 255, 255};
    static const GLubyte black[16] = {0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, four);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    /* One pixel covering the 2 x 2 texture: rho = 2, lambda = 1, level 1 (the mean). */
    quad_z(0, 24, 1, 25, 0, 1, 1);
    CHECK_PIXEL(0, 24, 128, 128, 128, 255, 1);
    /* Flag off, new level 0: level 1 keeps the old mean. */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
    quad_z(1, 24, 2, 25, 0, 1, 1);
    CHECK_PIXEL(1, 24, 128, 128, 128, 255, 1);
    quad_z(2, 24, 4, 26, 0, 1, 1); /* magnified: level 0 */
    CHECK_PIXEL(2, 24, 0, 0, 0, 255, 0);
    /* Flag on again, a sub-image upload regenerates the chain. */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, black);
    quad_z(4, 24, 5, 25, 0, 1, 1);
    CHECK_PIXEL(4, 24, 0, 0, 0, 255, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    CHECK_GL(GL_NO_ERROR);
}

static void point_sprite_coordinates_start_at_the_upper_left(void)
{
    static const GLubyte t[4 * 4 * 4] = {
        255, 0,   0,   255, 0,   255, 0,   255, 0,   0,   255, 255, 255, 255, 255, 255,
        10,  20,  30,  40,  50,  60,  70,  80,  90,  100, 110, 120, 130, 140, 150, 160,
        1,   2,   3,   4,   5,   6,   7,   8,   9,   10,  11,  12,  13,  14,  15,  16,
        200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215,
    };
    static const GLfloat p[3] = {24, 24, 0};
    int i, j;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_POINT_SPRITE_OES);
    glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, GL_TRUE);
    glPointSize(4);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, p);
    glDrawArrays(GL_POINTS, 0, 1);
    /* Pixels 22..25 in x and y; window row 25 (top) is t = 1/8: texel row 0 (bottom). */
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            const GLubyte *e = &t[((3 - j) * 4 + i) * 4];
            CHECK_PIXEL(22 + i, 22 + j, e[0], e[1], e[2], e[3], 0);
        }
    glDisable(GL_POINT_SPRITE_OES);
    glPointSize(1);
    CHECK_GL(GL_NO_ERROR);
}

int main(void)
{
    ct_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glOrthof(0, W, 0, H, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_TEXTURE_2D);
    glDisable(GL_DITHER);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    basic_modes_with_exact_colors();
    combine_functions();
    linear_fog_at_a_known_depth();
    generate_mipmap_toggled_between_uploads();
    point_sprite_coordinates_start_at_the_upper_left();
    ct_save("texenv");
    return ct_done();
}
