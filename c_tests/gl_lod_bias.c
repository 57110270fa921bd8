/*
 * EXT_texture_lod_bias: the per-unit GL_TEXTURE_LOD_BIAS_EXT of the
 * GL_TEXTURE_FILTER_CONTROL_EXT environment target (state, queries, errors), and its effect:
 * added to lambda before the minification / magnification decision and the level selection.
 * A mipmapped texture whose levels are distinct solid colors, drawn at 1:1 (lambda = 0),
 * shows level 0 without bias and level 1 exactly with a bias of +1, for every mipmap filter;
 * a 2:1 minified quad goes back to level 0 with a bias of -1; a bias beyond the maximum is
 * clamped; NEAREST / LINEAR textures (no mipmaps) are unaffected.
 */
#include "common.h"

#define W 32
#define H 32
#define N 8 /* level 0 is N x N */

/* Level colors: red, green, blue, white (levels 0 .. 3 of an 8 x 8 texture). */
static const GLubyte level_color[4][4] = {
    {255, 0, 0, 255},
    {0, 255, 0, 255},
    {0, 0, 255, 255},
    {255, 255, 255, 255},
};

static void quad(float x0, float y0, float x1, float y1)
{
    GLfloat v[8] = {x0, y0, x1, y0, x0, y1, x1, y1};
    GLfloat st[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* A complete 8 x 8 mip chain, level l filled with level_color[l]. */
static GLuint mip_texture(void)
{
    static GLubyte texels[N * N * 4];
    GLuint name;
    int level, size, i;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (level = 0, size = N; size >= 1; ++level, size /= 2) {
        for (i = 0; i < size * size; ++i)
            memcpy(&texels[i * 4], level_color[level], 4);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     texels);
    }
    return name;
}

static void check_level(int x0, int y0, int size, int level)
{
    const GLubyte *c = level_color[level];
    CHECK_PIXEL(x0, y0, c[0], c[1], c[2], c[3], 0);
    CHECK_PIXEL(x0 + size - 1, y0 + size - 1, c[0], c[1], c[2], c[3], 0);
    CHECK_PIXEL(x0 + size / 2, y0 + size / 2 - 1, c[0], c[1], c[2], c[3], 0);
}

static void state_defaults_round_trips_and_errors(void)
{
    GLfloat f = -1, max = 0;
    GLint i = -1;
    GLfixed x = -1;
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    CHECK(ext != NULL && strstr(ext, "GL_EXT_texture_lod_bias") != NULL);

    glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS_EXT, &max);
    CHECK(max >= 2.0f);
    if (ct_strict())
        CHECK(max == 16.0f);
    CHECK_GL(GL_NO_ERROR);

    /* Default 0 on every unit. */
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK(f == 0.0f);
    glActiveTexture(GL_TEXTURE1);
    glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &i);
    CHECK(i == 0);
    CHECK_GL(GL_NO_ERROR);

    /* Per unit: a bias set on unit 1 leaves unit 0 alone. */
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, 1.5f);
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK(f == 1.5f);
    glGetTexEnvxv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &x);
    CHECK(x == 0x18000);
    glActiveTexture(GL_TEXTURE0);
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK(f == 0.0f);
    glActiveTexture(GL_TEXTURE1);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, 0.0f);
    glActiveTexture(GL_TEXTURE0);
    CHECK_GL(GL_NO_ERROR);

    /* Every form of the call. */
    glTexEnvi(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, -3);
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK(f == -3.0f);
    glTexEnvx(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, 0x28000); /* 2.5 */
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK(f == 2.5f);
    {
        GLfloat fv = -0.25f;
        GLint iv = 2;
        GLfixed xv = -0x10000;
        glTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &fv);
        glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
        CHECK(f == -0.25f);
        glTexEnviv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &iv);
        glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &i);
        CHECK(i == 2);
        glTexEnvxv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &xv);
        glGetTexEnvxv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &x);
        CHECK(x == -0x10000);
    }
    CHECK_GL(GL_NO_ERROR);

    /* Errors: the bias under the wrong target, other names under the filter control target;
     * none changes the state. */
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS_EXT, 1.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_ENV_MODE, &i);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, &f);
    CHECK(f == -1.0f);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &i);
    CHECK(i == GL_MODULATE);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, 0.0f);
    CHECK_GL(GL_NO_ERROR);
}

static void bias(float b)
{
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT, b);
}

static void bias_moves_the_level(GLenum min, GLenum mag)
{
    clear();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
    /* 1:1, lambda = 0: level 0, then level 1 with +1, level 2 with +2. */
    bias(0);
    quad(0, 0, N, N);
    bias(1);
    quad(N, 0, 2 * N, N);
    bias(2);
    quad(2 * N, 0, 3 * N, N);
    /* A bias past the maximum is clamped to it: the last level. */
    bias(1000);
    quad(3 * N, 0, 4 * N, N);
    /* 2:1 minified (a 4 x 4 quad), lambda = 1: level 1, back to level 0 with -1. */
    bias(0);
    quad(0, N, N / 2, N + N / 2);
    bias(-1);
    quad(N, N, N + N / 2, N + N / 2);
    bias(0);
    check_level(0, 0, N, 0);
    check_level(N, 0, N, 1);
    check_level(2 * N, 0, N, 2);
    check_level(3 * N, 0, N, 3);
    check_level(0, N, N / 2, 1);
    check_level(N, N, N / 2, 0);
    CHECK_GL(GL_NO_ERROR);
}

static void filters_without_mipmaps_ignore_the_bias(void)
{
    GLenum filters[2] = {GL_NEAREST, GL_LINEAR};
    int k;
    for (k = 0; k < 2; ++k) {
        clear();
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filters[k]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filters[k]);
        bias(4);
        quad(0, 0, N, N);
        quad(N, 0, N + N / 2, N / 2);
        bias(0);
        check_level(0, 0, N, 0);
        check_level(N, 0, N / 2, 0);
    }
    CHECK_GL(GL_NO_ERROR);
}

/* With LINEAR magnification and NEAREST_MIPMAP_NEAREST the switch-over point is 1/2: a bias
 * of 0.25 at 1:1 stays magnification (level 0), 0.75 takes level 1. */
static void switch_over_point_sees_the_bias(void)
{
    clear();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    bias(0.25f);
    quad(0, 0, N, N);
    bias(0.75f);
    quad(N, 0, 2 * N, N);
    bias(0);
    check_level(0, 0, N, 0);
    check_level(N, 0, N, 1);
    CHECK_GL(GL_NO_ERROR);
}

int main(void)
{
    GLuint tex;
    ct_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_DITHER);

    state_defaults_round_trips_and_errors();

    tex = mip_texture();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    bias_moves_the_level(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
    ct_save("nearest_mipmap_nearest");
    bias_moves_the_level(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
    bias_moves_the_level(GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST);
    bias_moves_the_level(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    ct_save("linear_mipmap_linear");
    filters_without_mipmaps_ignore_the_bias();
    switch_over_point_sees_the_bias();
    glDeleteTextures(1, &tex);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
