/*
 * Texture environments (per texture unit) and point sprite coordinate replacement.
 *
 * Checks made only under ct_strict(), where Mesa departs from the specification: Mesa keeps
 * TEXTURE_ENV_COLOR unclamped and accepts it through the single-value commands.
 */
#include "common.h"

static GLint envi(GLenum target, GLenum pname)
{
    GLint v = -12345;
    glGetTexEnviv(target, pname, &v);
    return v;
}

static GLfloat envf(GLenum pname)
{
    GLfloat v = -12345.0f;
    glGetTexEnvfv(GL_TEXTURE_ENV, pname, &v);
    return v;
}

static GLfixed envx(GLenum pname)
{
    GLfixed v = -12345;
    glGetTexEnvxv(GL_TEXTURE_ENV, pname, &v);
    return v;
}

int main(void)
{
    static const GLenum src[6] = {GL_SRC0_RGB, GL_SRC1_RGB, GL_SRC2_RGB,
                                  GL_SRC0_ALPHA, GL_SRC1_ALPHA, GL_SRC2_ALPHA};
    static const GLenum src_default[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
    static const GLenum op[6] = {GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB,
                                 GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA};
    static const GLenum modes[6] = {GL_MODULATE, GL_REPLACE, GL_DECAL,
                                    GL_BLEND, GL_ADD, GL_COMBINE};
    static const GLenum combine_rgb[8] = {GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED,
                                          GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB,
                                          GL_DOT3_RGBA};
    GLfloat f[4];
    GLfixed x[4];
    GLint iv[4];
    GLint units = 0, i;

    ct_init(16, 16);
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    CHECK(units >= 2);

    /* Defaults, on every unit. */
    for (i = 0; i < units; ++i) {
        int k;
        glActiveTexture(GL_TEXTURE0 + (GLenum)i);
        CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_MODULATE);
        glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
        CHECK(f[0] == 0 && f[1] == 0 && f[2] == 0 && f[3] == 0);
        CHECK(envi(GL_TEXTURE_ENV, GL_COMBINE_RGB) == GL_MODULATE);
        CHECK(envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA) == GL_MODULATE);
        for (k = 0; k < 6; ++k)
            CHECK(envi(GL_TEXTURE_ENV, src[k]) == (GLint)src_default[k % 3]);
        CHECK(envi(GL_TEXTURE_ENV, GL_OPERAND0_RGB) == GL_SRC_COLOR);
        CHECK(envi(GL_TEXTURE_ENV, GL_OPERAND1_RGB) == GL_SRC_COLOR);
        CHECK(envi(GL_TEXTURE_ENV, GL_OPERAND2_RGB) == GL_SRC_ALPHA);
        for (k = 3; k < 6; ++k)
            CHECK(envi(GL_TEXTURE_ENV, op[k]) == GL_SRC_ALPHA);
        CHECK(envf(GL_RGB_SCALE) == 1.0f);
        CHECK(envf(GL_ALPHA_SCALE) == 1.0f);
        CHECK(envi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) == GL_FALSE);
    }
    glActiveTexture(GL_TEXTURE0);
    CHECK_GL(GL_NO_ERROR);

    /* Mode through every setter; enumerants pass unconverted through the fixed ones. */
    for (i = 0; i < 6; ++i) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[i]);
        CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == (GLint)modes[i]);
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLfloat)GL_ADD);
    CHECK(envf(GL_TEXTURE_ENV_MODE) == (GLfloat)GL_ADD);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    CHECK(envx(GL_TEXTURE_ENV_MODE) == GL_DECAL);
    f[0] = (GLfloat)GL_BLEND;
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, f);
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_BLEND);
    iv[0] = GL_REPLACE;
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_REPLACE);
    x[0] = GL_COMBINE;
    glTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, x);
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_COMBINE);
    CHECK_GL(GL_NO_ERROR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_SUBTRACT);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, 0.5f);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE << 16);
    CHECK_GL(GL_INVALID_ENUM);
    iv[0] = GL_DOT3_RGB;
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_COMBINE);

    /* Combine functions. */
    for (i = 0; i < 8; ++i) {
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)combine_rgb[i]);
        CHECK(envi(GL_TEXTURE_ENV, GL_COMBINE_RGB) == (GLint)combine_rgb[i]);
    }
    for (i = 0; i < 6; ++i) {
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)combine_rgb[i]);
        CHECK(envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA) == (GLint)combine_rgb[i]);
    }
    CHECK_GL(GL_NO_ERROR);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGBA);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DECAL);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(envi(GL_TEXTURE_ENV, GL_COMBINE_RGB) == GL_DOT3_RGBA);
    CHECK(envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA) == GL_SUBTRACT);
    glTexEnvx(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    CHECK(envx(GL_COMBINE_RGB) == GL_INTERPOLATE);

    /* Sources and operands. */
    for (i = 0; i < 6; ++i) {
        glTexEnvi(GL_TEXTURE_ENV, src[i], GL_PRIMARY_COLOR);
        CHECK(envi(GL_TEXTURE_ENV, src[i]) == GL_PRIMARY_COLOR);
        glTexEnvf(GL_TEXTURE_ENV, src[i], (GLfloat)GL_CONSTANT);
        CHECK(envi(GL_TEXTURE_ENV, src[i]) == GL_CONSTANT);
        glTexEnvi(GL_TEXTURE_ENV, src[i], GL_ZERO);
        CHECK_GL(GL_INVALID_ENUM);
        glTexEnvi(GL_TEXTURE_ENV, op[i], GL_ONE_MINUS_SRC_ALPHA);
        CHECK(envi(GL_TEXTURE_ENV, op[i]) == GL_ONE_MINUS_SRC_ALPHA);
        glTexEnvi(GL_TEXTURE_ENV, op[i], GL_ONE);
        CHECK_GL(GL_INVALID_ENUM);
        CHECK(envi(GL_TEXTURE_ENV, op[i]) == GL_ONE_MINUS_SRC_ALPHA);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_COLOR);
    CHECK(envi(GL_TEXTURE_ENV, GL_OPERAND1_RGB) == GL_ONE_MINUS_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_SRC_COLOR);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_ONE_MINUS_SRC_COLOR);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(envi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA) == GL_ONE_MINUS_SRC_ALPHA);
    CHECK_GL(GL_NO_ERROR);

    /* Scales: 1, 2 or 4 only. */
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(envf(GL_RGB_SCALE) == 2.0f);
    CHECK(envi(GL_TEXTURE_ENV, GL_RGB_SCALE) == 2);
    CHECK(envx(GL_RGB_SCALE) == 0x20000);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4);
    CHECK(envf(GL_ALPHA_SCALE) == 4.0f);
    glTexEnvx(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0x10000);
    CHECK(envx(GL_ALPHA_SCALE) == 0x10000);
    f[0] = 4.0f;
    glTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, f);
    CHECK(envi(GL_TEXTURE_ENV, GL_RGB_SCALE) == 4);
    x[0] = 0x20000;
    glTexEnvxv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, x);
    CHECK(envf(GL_ALPHA_SCALE) == 2.0f);
    CHECK_GL(GL_NO_ERROR);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f);
    CHECK_GL(GL_INVALID_VALUE);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.5f);
    CHECK_GL(GL_INVALID_VALUE);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0);
    CHECK_GL(GL_INVALID_VALUE);
    glTexEnvx(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
    CHECK_GL(GL_INVALID_VALUE);
    iv[0] = 8;
    glTexEnviv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, iv);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(envf(GL_RGB_SCALE) == 4.0f);
    CHECK(envf(GL_ALPHA_SCALE) == 2.0f);

    /* Color: float, fixed and integer (mapped from the integer range). */
    f[0] = 0.25f;
    f[1] = 0.5f;
    f[2] = 0.75f;
    f[3] = 1.0f;
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    CHECK_GL(GL_NO_ERROR);
    glGetTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, x);
    CHECK(x[0] == 0x4000 && x[1] == 0x8000 && x[2] == 0xc000 && x[3] == 0x10000);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, iv);
    CHECK(iv[3] == 0x7fffffff && (iv[1] == 0x3fffffff || iv[1] == 0x40000000));
    x[0] = 0x10000;
    x[1] = 0;
    x[2] = 0x8000;
    x[3] = 0x4000;
    glTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, x);
    CHECK_GL(GL_NO_ERROR);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    CHECK(f[0] == 1.0f && f[1] == 0.0f && f[2] == 0.5f && f[3] == 0.25f);
    iv[0] = 0x7fffffff;
    iv[1] = 0x3fffffff;
    iv[2] = 0x7fffffff;
    iv[3] = 0x7fffffff;
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, iv);
    CHECK_GL(GL_NO_ERROR);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    CHECK(f[0] == 1.0f && f[1] == 0.5f && f[3] == 1.0f);
    f[0] = 2.0f;
    f[1] = -1.0f;
    f[2] = 0.5f;
    f[3] = 0.0f;
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    CHECK_GL(GL_NO_ERROR);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    CHECK(f[2] == 0.5f && f[3] == 0.0f);
    if (ct_strict()) {
        CHECK(f[0] == 1.0f && f[1] == 0.0f);
        glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 1.0f);
        CHECK_GL(GL_INVALID_ENUM);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 1);
        CHECK_GL(GL_INVALID_ENUM);
        glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0x10000);
        CHECK_GL(GL_INVALID_ENUM);
    }

    /* Targets and names. */
    glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_ADD);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, (GLfloat)GL_NEAREST);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvx(GL_FOG, GL_RGB_SCALE, 0x10000);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_COLOR, f);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnviv(GL_TEXTURE_ENV, GL_COORD_REPLACE_OES, iv);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvxv(GL_POINT_SPRITE_OES, GL_TEXTURE_ENV_MODE, x);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnviv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, iv);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_COORD_REPLACE_OES, f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnvxv(GL_POINT_SPRITE_OES, GL_RGB_SCALE, x);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_2D, x);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_COMBINE);

    /* Point sprite coordinate replacement, per unit. */
    glActiveTexture(GL_TEXTURE1);
    glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, GL_TRUE);
    CHECK_GL(GL_NO_ERROR);
    CHECK(envi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) == GL_TRUE);
    glGetTexEnvfv(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, f);
    CHECK(f[0] == 1.0f);
    glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, 2);
    CHECK_GL(GL_INVALID_VALUE);
    x[0] = 0x10000; /* fixed point passes booleans unconverted: 65536 is no boolean */
    glTexEnvxv(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, x);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(envi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) == GL_TRUE);
    /* The texture environment of unit 1 is its own. */
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_MODULATE);
    CHECK(envf(GL_RGB_SCALE) == 1.0f);
    glTexEnvf(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, 0.0f);
    CHECK(envi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) == GL_FALSE);
    glActiveTexture(GL_TEXTURE0);
    CHECK(envi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) == GL_FALSE);
    glTexEnvx(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, GL_TRUE);
    CHECK(envi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) == GL_TRUE);
    CHECK(envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) == GL_COMBINE);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
