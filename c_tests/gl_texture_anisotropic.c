/*
 * EXT_texture_filter_anisotropic: GL_TEXTURE_MAX_ANISOTROPY_EXT per texture object (initial
 * 1, at least 1 or GL_INVALID_VALUE, in every parameter form), GL_MAX_TEXTURE_MAX_
 * ANISOTROPY_EXT of at least 2, and what the limit does to a footprint four texels long
 * and one wide. Each mipmap level is one color, so the level a pixel reads is exact.
 * The extension leaves the filter to the implementation: only the isotropic result is
 * checked everywhere; ours follows the extension's suggested filter (N = min(ceil(P_max /
 * P_min), limit) samples at lambda = log2(P_max / N)), checked on this library only.
 */
#include "common.h"
#include <GLES/glext.h>

#define W 48
#define H 16

static const GLubyte colors[3][4] = {{255, 255, 255, 255}, {0, 255, 0, 255}, {255, 0, 0, 255}};

/* A 64 × 16 texture whose level 0 is white, level 1 green, level 2 red, the rest blue. */
static void upload_levels(void)
{
    static GLubyte texels[64 * 16 * 4];
    GLsizei w = 64, h = 16;
    for (int level = 0; w >= 1 && h >= 1; ++level) {
        static const GLubyte blue[4] = {0, 0, 255, 255};
        const GLubyte *c = level < 3 ? colors[level] : blue;
        for (int i = 0; i < w * h; ++i)
            memcpy(texels + 4 * i, c, 4);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        if (w == 1 && h == 1)
            break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* A quad of w × h pixels at (x, 0) over the whole texture; `turned` runs s up the quad
 * and t across it. */
static void quad(int x, int w, int h, int turned)
{
    GLfloat v[8] = {x, 0, x + w, 0, x, h, x + w, h};
    GLfloat st[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    GLfloat ts[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, turned ? ts : st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void parameter_forms_and_errors(void)
{
    GLfloat f = 0, max = 0;
    GLint i = 0;
    GLfixed x = 0;
    GLenum e;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &max);
    CHECK(max >= 2.0f);
    glGetIntegerv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &i);
    CHECK(i >= 2);
    CHECK_GL(GL_NO_ERROR);

    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK(f == 1.0f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 2.0f);
    CHECK_GL(GL_NO_ERROR);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK(f == 2.0f);
    /* Below 1: GL_INVALID_VALUE in each form, the value kept. */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0);
    CHECK_GL(GL_INVALID_VALUE);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0x8000);
    CHECK_GL(GL_INVALID_VALUE);
    f = -1.0f;
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK_GL(GL_INVALID_VALUE);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK(f == 2.0f);
    /* The integer and fixed-point forms convert like any other value. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 3);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &i);
    CHECK(i == 3);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0x18000);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK(f == 1.5f);
    glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &x);
    e = glGetError();
    CHECK_MESA_DEVIATES(e == GL_NO_ERROR && x == 0x18000,
                        "Mesa's glGetTexParameterxv refuses the name: GL_INVALID_ENUM");
    /* Past the limit: kept as set or clamped to it (the extension allows both). */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, max * 4.0f);
    CHECK_GL(GL_NO_ERROR);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK(f == max * 4.0f || f == max);
    /* A cube map has its own; an unknown target is still GL_INVALID_ENUM. */
    glTexParameterf(GL_TEXTURE_CUBE_MAP_OES, GL_TEXTURE_MAX_ANISOTROPY_EXT, 2.0f);
    CHECK_GL(GL_NO_ERROR);
    glGetTexParameterfv(GL_TEXTURE_CUBE_MAP_OES, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    CHECK(f == 2.0f);
    glTexParameterf(GL_TEXTURE_ENV, GL_TEXTURE_MAX_ANISOTROPY_EXT, 2.0f);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 1.0f);
    CHECK_GL(GL_NO_ERROR);
}

/* The pixel (x, 8) has the color of level `level`. */
static void check_level(int x, int level, int strict_only)
{
    if (strict_only && !ct_strict())
        return;
    CHECK_PIXEL(x, 8, colors[level][0], colors[level][1], colors[level][2], 255, 0);
}

static void the_limit_sharpens_long_footprints(void)
{
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    upload_levels();
    glEnable(GL_TEXTURE_2D);
    /* 64 texels over 16 pixels across, 16 over 16 up: P_max 4, P_min 1. Isotropic: level
     * 2 (lambda 2), whatever the implementation. */
    quad(0, 16, 16, 0);
    check_level(8, 2, 0);
    /* Limit 2: two samples at lambda 1, level 1. */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 2.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 16, 16, 0);
    check_level(8, 1, 1);
    /* The same footprint turned (the long axis up the screen). */
    quad(16, 16, 16, 1);
    check_level(24, 1, 1);
    /* Limit 16: four samples at lambda 0, level 0; a limit of 3 also reads level 0
     * (lambda log2(4/3) rounds to it). */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 16.0f);
    quad(0, 16, 16, 0);
    check_level(8, 0, 1);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 3.0f);
    quad(16, 16, 16, 1);
    check_level(24, 0, 1);
    /* A square footprint (4 texels each way) stays isotropic at any limit: level 2. */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 16.0f);
    quad(32, 16, 4, 0);
    CHECK_PIXEL(40, 2, 255, 0, 0, 255, 0);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);
    CHECK_GL(GL_NO_ERROR);
}

int main(void)
{
    ct_init(W, H);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    CHECK(ext != NULL && strstr(ext, "GL_EXT_texture_filter_anisotropic") != NULL);
    glMatrixMode(GL_PROJECTION);
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_DITHER);
    parameter_forms_and_errors();
    the_limit_sharpens_long_footprints();
    return ct_done();
}
