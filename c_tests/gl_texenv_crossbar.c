/*
 * OES_texture_env_crossbar: a COMBINE source GL_TEXTUREn reads unit n's texel, filtered
 * with unit n's own coordinates and sampler, from any unit (before or after it); ours makes
 * a unit whose combiner names a unit that is disabled or has no complete texture act as if
 * its texturing were disabled. GL_TEXTUREn past GL_MAX_TEXTURE_UNITS is GL_INVALID_ENUM.
 * Texel and color values are multiples of 1/255 whose products round unambiguously, so
 * the pixels are exact.
 */
#include "common.h"

#define W 32
#define H 16

static GLuint tex[3];

/* A 2 × 2 quad at (x, y): unit 0's coordinates are (0, 0) everywhere, unit 1's run from
 * s = 0 on the left column to s = 1 on the right one. */
static void quad(int x, int y)
{
    GLfloat v[8] = {x, y, x + 2, y, x, y + 2, x + 2, y + 2};
    GLfloat st0[8] = {0.25f, 0.5f, 0.25f, 0.5f, 0.25f, 0.5f, 0.25f, 0.5f};
    GLfloat st1[8] = {0.25f, 0.5f, 0.75f, 0.5f, 0.25f, 0.5f, 0.75f, 0.5f};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st0);
    glClientActiveTexture(GL_TEXTURE1);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void upload(GLuint name, GLsizei w, const GLubyte *rgba)
{
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* Unit `unit`: COMBINE with `func` of sources s0 and s1 for RGB and alpha alike. */
static void combine(GLenum unit, GLenum func, GLenum s0, GLenum s1)
{
    glActiveTexture(unit);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, func);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, s0);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA, s0);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, s1);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_ALPHA, s1);
}

static void sources_are_validated_and_queried(void)
{
    GLint units = 0, v = 0;
    GLfloat f = 0;
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    CHECK(units >= 2);
    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE1);
    CHECK_GL(GL_NO_ERROR);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC0_RGB, &v);
    CHECK(v == GL_TEXTURE1);
    glTexEnvf(GL_TEXTURE_ENV, GL_SRC2_ALPHA, (GLfloat)(GL_TEXTURE0 + units - 1));
    CHECK_GL(GL_NO_ERROR);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_SRC2_ALPHA, &f);
    CHECK(f == (GLfloat)(GL_TEXTURE0 + units - 1));
    /* One past the last unit, and far past it: the value stays. */
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE0 + units);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_ALPHA, GL_TEXTURE31);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC0_RGB, &v);
    CHECK(v == GL_TEXTURE1);
    /* GL_TEXTUREn is a source, not an operand or a function. */
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_TEXTURE1);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_TEXTURE1);
    CHECK_GL(GL_INVALID_ENUM);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC2_ALPHA, GL_CONSTANT);
    CHECK_GL(GL_NO_ERROR);
}

static void units_read_each_other(void)
{
    /* A = (1, 0.5, 0, 1) on unit 0; B = black | (0.2, 0.4, 0.8, 0.6) on unit 1. */
    static const GLubyte a[4] = {255, 128, 0, 255};
    static const GLubyte b[8] = {0, 0, 0, 255, 51, 102, 204, 153};
    static const GLubyte white[8] = {255, 255, 255, 255, 255, 255, 255, 255};
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_TEXTURE_2D);
    upload(tex[0], 1, a);
    glActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    upload(tex[1], 2, b);
    glColor4f(0.0f, 1.0f, 0.0f, 1.0f);

    /* Unit 0 replaces with unit 1's texel (at unit 1's coordinates); unit 1 passes it on. */
    combine(GL_TEXTURE0, GL_REPLACE, GL_TEXTURE1, GL_PREVIOUS);
    combine(GL_TEXTURE1, GL_REPLACE, GL_PREVIOUS, GL_PREVIOUS);
    quad(0, 0);
    CHECK_PIXEL(0, 0, 0, 0, 0, 255, 0);
    CHECK_PIXEL(1, 1, 51, 102, 204, 153, 0);

    /* A later unit reads an earlier one: B × A = (0.2, 0.2, 0, 0.6), B's left texel × A =
     * black. */
    combine(GL_TEXTURE1, GL_MODULATE, GL_PREVIOUS, GL_TEXTURE0);
    quad(4, 0);
    CHECK_PIXEL(4, 0, 0, 0, 0, 255, 0);
    CHECK_PIXEL(5, 1, 51, 51, 0, 153, 0);

    /* GL_TEXTURE0 on unit 0 is unit 0's own texel, as GL_TEXTURE is. */
    combine(GL_TEXTURE0, GL_REPLACE, GL_TEXTURE0, GL_PREVIOUS);
    combine(GL_TEXTURE1, GL_REPLACE, GL_PREVIOUS, GL_PREVIOUS);
    quad(8, 0);
    CHECK_PIXEL(9, 1, 255, 128, 0, 255, 0);

    /* Unit 1 with another texture (white): unit 0 = white × A = A, and unit 1 (MODULATE)
     * multiplies by its own white texel. */
    combine(GL_TEXTURE0, GL_MODULATE, GL_TEXTURE1, GL_TEXTURE);
    glActiveTexture(GL_TEXTURE1);
    upload(tex[2], 2, white);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    quad(12, 0);
    CHECK_PIXEL(13, 1, 255, 128, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);
}

/*
 * Naming a unit that is disabled or incomplete: ARB_texture_env_crossbar, which the OES
 * extension carries to ES, makes the naming unit act as if its texturing were disabled;
 * later GL versions leave the result undefined, and Mesa reads zeros there. Checked on this
 * library only, and drawn after the image is saved.
 */
static void naming_a_missing_unit(void)
{
    int strict = ct_strict();
    /* Unit 1 disabled: unit 0, which names it, passes the primary color through. */
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    quad(16, 0);
    if (strict)
        CHECK_PIXEL(17, 1, 0, 255, 0, 255, 0);

    /* Unit 1 enabled with an incomplete texture (mipmapped filter, level 0 of two). */
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    quad(20, 0);
    if (strict)
        CHECK_PIXEL(21, 1, 0, 255, 0, 255, 0);

    /* Unit 0 disabled: unit 1 (complete again) naming it passes its input, the primary
     * color, through. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    combine(GL_TEXTURE1, GL_ADD, GL_TEXTURE0, GL_TEXTURE);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_TEXTURE_2D);
    quad(24, 0);
    if (strict)
        CHECK_PIXEL(25, 1, 0, 255, 0, 255, 0);
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    CHECK_GL(GL_NO_ERROR);
}

int main(void)
{
    ct_init(W, H);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    CHECK(ext != NULL && strstr(ext, "GL_OES_texture_env_crossbar") != NULL);
    glMatrixMode(GL_PROJECTION);
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_DITHER);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glGenTextures(3, tex);
    sources_are_validated_and_queried();
    units_read_each_other();
    ct_save("texenv_crossbar");
    naming_a_missing_unit();
    return ct_done();
}
