/* OES_compressed_ETC1_RGB8_texture (decoded on upload; sub-image updates through
 * EXT_compressed_ETC1_RGB8_sub_texture) and EXT_texture_format_BGRA8888 (BGRA client data
 * with GL_UNSIGNED_BYTE). */
#include "common.h"

static int has_ext(const char *name)
{
    const char *e = (const char *)glGetString(GL_EXTENSIONS);
    return e != NULL && strstr(e, name) != NULL;
}

static void draw_textured(void)
{
    GLfloat v[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    GLfloat st[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void etc1(void)
{
    /* Block 0 (left 4 × 4): individual mode, no flip, left subblock base 0xf00 (red), right
     * subblock 0x00f (blue), table 0, every pixel index 0 (+2): (255, 2, 2) and (2, 2, 255).
     * Block 1 (right 4 × 4): differential mode, flip, top base 5-bit (0, 31, 0), delta
     * (+3, 0, 0) for the bottom; table 0, all +2: top (2, 255, 2), bottom (26, 255, 2). */
    static const GLubyte blocks[16] = {0xf0, 0x00, 0x0f, 0x00, 0, 0, 0, 0,
                                       0x03, 0xf8, 0x00, 0x03, 0, 0, 0, 0};
    GLint n = 0, i, listed[64], found = 0;
    GLuint tex = 0;

    glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &n);
    CHECK(n > 0 && n <= 64);
    if (n > 64)
        n = 64;
    glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, listed);
    for (i = 0; i < n; ++i)
        found |= listed[i] == GL_ETC1_RGB8_OES;
    CHECK(found);

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_ETC1_RGB8_OES, 8, 4, 0, 16, blocks);
    CHECK_GL(GL_NO_ERROR);

    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    draw_textured(); /* 32 × 16 surface: each texel is 4 × 4 pixels */
    CHECK_PIXEL(2, 2, 255, 2, 2, 255, 0);
    CHECK_PIXEL(10, 14, 2, 2, 255, 255, 0);
    CHECK_PIXEL(18, 2, 2, 255, 2, 255, 0);
    CHECK_PIXEL(30, 14, 26, 255, 2, 255, 0);
    ct_save("etc1");
    glDisable(GL_TEXTURE_2D);

    /* Errors: a size that does not match the blocks, a bad level, a border. */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_ETC1_RGB8_OES, 8, 4, 0, 8, blocks);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, -1, GL_ETC1_RGB8_OES, 4, 4, 0, 8, blocks);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_ETC1_RGB8_OES, 4, 4, 1, 8, blocks);
    CHECK_GL(GL_INVALID_VALUE);
    /* Smaller than a block: one whole block of data. */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_ETC1_RGB8_OES, 2, 1, 0, 8, blocks);
    CHECK_GL(GL_NO_ERROR);
    /* A whole-level update reaching the edges (EXT_compressed_ETC1_RGB8_sub_texture; the
     * rest of its rules are in gl_compressed_blocks.c). */
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 1, GL_ETC1_RGB8_OES, 8, blocks);
    CHECK_GL(GL_NO_ERROR);
    glDeleteTextures(1, &tex);
}

static void bgra(void)
{
    /* Bottom row: (B, G, R, A) = red, green; top row: blue, half-transparent white. */
    static const GLubyte texels[16] = {0, 0, 255, 255, 0, 255, 0, 255,
                                       255, 0, 0, 255, 255, 255, 255, 128};
    GLuint tex = 0;

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_BGRA_EXT, 2, 2, 0, GL_BGRA_EXT, GL_UNSIGNED_BYTE, texels);
    CHECK_GL(GL_NO_ERROR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClear(GL_COLOR_BUFFER_BIT);
    draw_textured();
    CHECK_PIXEL(4, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(20, 4, 0, 255, 0, 255, 0);
    CHECK_PIXEL(4, 12, 0, 0, 255, 255, 0);
    CHECK_PIXEL(20, 12, 255, 255, 255, 128, 0);
    ct_save("bgra");

    /* Sub-image updates in BGRA. */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_BYTE, texels + 8);
    CHECK_GL(GL_NO_ERROR);
    draw_textured();
    CHECK_PIXEL(4, 4, 0, 0, 255, 255, 0);
    glDisable(GL_TEXTURE_2D);

    /* Only with GL_UNSIGNED_BYTE. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_BGRA_EXT, 2, 2, 0, GL_BGRA_EXT, GL_UNSIGNED_SHORT_4_4_4_4,
                 texels);
    CHECK(glGetError() != GL_NO_ERROR);
    CHECK_GL(GL_NO_ERROR);
    glDeleteTextures(1, &tex);
}

int main(void)
{
    ct_init(32, 16);
    CHECK(has_ext("GL_OES_compressed_ETC1_RGB8_texture"));
    etc1();
    /* Mesa's ES 1 does not always list BGRA8888; ours must. */
    if (ct_strict())
        CHECK(has_ext("GL_EXT_texture_format_BGRA8888"));
    if (has_ext("GL_EXT_texture_format_BGRA8888"))
        bgra();
    else
        ct_save("bgra");
    return ct_done();
}
