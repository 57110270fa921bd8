/* OES_compressed_paletted_texture: formats, size checks, levels from one blob, sub-images. */
#include "common.h"

static GLint get_int(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

/* Where Mesa (the differential oracle) departs from the ES 1.1 specification, the check
 * runs only against this library: Mesa ignores the border of paletted images and exposes
 * OES_texture_npot; it also refuses sub-images of paletted textures with INVALID_VALUE). */
#define CHECK_GL_SPEC(expected)                                                          \
    do {                                                                                 \
        if (strict)                                                                      \
            CHECK_GL(expected);                                                          \
        else                                                                             \
            (void)glGetError();                                                          \
    } while (0)

int main(void)
{
    int strict;
    static const GLenum formats[10] = {
        GL_PALETTE4_RGB8_OES,  GL_PALETTE4_RGBA8_OES, GL_PALETTE4_R5_G6_B5_OES,
        GL_PALETTE4_RGBA4_OES, GL_PALETTE4_RGB5_A1_OES, GL_PALETTE8_RGB8_OES,
        GL_PALETTE8_RGBA8_OES, GL_PALETTE8_R5_G6_B5_OES, GL_PALETTE8_RGBA4_OES,
        GL_PALETTE8_RGB5_A1_OES,
    };
    static const int entry_size[5] = {3, 4, 2, 2, 2};
    static GLubyte blob[256 * 4 + 64 * 64];
    GLint listed[64];
    GLuint tex = 0;
    int i, j, n;

    ct_init(16, 16);
    strict = ct_strict();

    n = get_int(GL_NUM_COMPRESSED_TEXTURE_FORMATS);
    CHECK(n >= 10 && n <= 64);
    if (n > 64)
        n = 64;
    glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, listed);
    for (i = 0; i < 10; ++i) {
        int found = 0;
        for (j = 0; j < n; ++j)
            found |= listed[j] == (GLint)formats[i];
        CHECK(found);
    }
    CHECK_GL(GL_NO_ERROR);

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);

    /* Every format, 4x4, one level and the whole chain (level -2: 4x4, 2x2, 1x1). */
    for (i = 0; i < 10; ++i) {
        int palette = (i < 5 ? 16 : 256) * entry_size[i % 5];
        int one = palette + (i < 5 ? 8 : 16);
        int chain = palette + (i < 5 ? 8 + 2 + 1 : 16 + 4 + 1);
        glCompressedTexImage2D(GL_TEXTURE_2D, 0, formats[i], 4, 4, 0, one, blob);
        CHECK_GL(GL_NO_ERROR);
        glCompressedTexImage2D(GL_TEXTURE_2D, -2, formats[i], 4, 4, 0, chain, blob);
        CHECK_GL(GL_NO_ERROR);
        glCompressedTexImage2D(GL_TEXTURE_2D, 0, formats[i], 4, 4, 0, one + 1, blob);
        CHECK_GL(GL_INVALID_VALUE);
        glCompressedTexImage2D(GL_TEXTURE_2D, 0, formats[i], 4, 4, 0, one - 1, blob);
        CHECK_GL(GL_INVALID_VALUE);
        glCompressedTexImage2D(GL_TEXTURE_2D, -2, formats[i], 4, 4, 0, one, blob);
        CHECK_GL(GL_INVALID_VALUE);
    }
    /* Odd texel counts round the 4-bit level up to whole bytes. */
    glCompressedTexImage2D(GL_TEXTURE_2D, -1, GL_PALETTE4_RGBA8_OES, 2, 1, 0, 64 + 1 + 1, blob);
    CHECK_GL(GL_NO_ERROR);

    /* Errors. */
    glCompressedTexImage2D(GL_TEXTURE_2D + 1, 0, GL_PALETTE8_RGB8_OES, 1, 1, 0, 769, blob);
    CHECK_GL(GL_INVALID_ENUM);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, 4, blob);
    CHECK_GL(GL_INVALID_ENUM);
    glCompressedTexImage2D(GL_TEXTURE_2D, 1, GL_PALETTE8_RGB8_OES, 1, 1, 0, 769, blob);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_RGB8_OES, 1, 1, 1, 769, blob);
    CHECK_GL_SPEC(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_RGB8_OES, -1, 1, 0, 769, blob);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_RGB8_OES, 3, 1, 0, 771, blob);
    CHECK_GL(GL_NO_ERROR); /* any size, with OES_texture_npot */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_RGB8_OES, 1, 1, 0, -1, blob);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, -40, GL_PALETTE8_RGB8_OES, 1, 1, 0, 768 + 41, blob);
    CHECK_GL(GL_INVALID_VALUE); /* more levels than the largest texture has */

    /* No sub-image updates of paletted textures. */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGB8_OES, 4, 4, 0, 56, blob);
    CHECK_GL(GL_NO_ERROR);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_PALETTE4_RGB8_OES, 50, blob);
    CHECK_GL_SPEC(GL_INVALID_OPERATION); /* ES 1.1 §3.7.3; Mesa says INVALID_VALUE */
    glCompressedTexSubImage2D(GL_TEXTURE_2D + 1, 0, 0, 0, 2, 2, GL_PALETTE4_RGB8_OES, 50, blob);
    CHECK(glGetError() != GL_NO_ERROR); /* INVALID_ENUM here; Mesa says INVALID_VALUE */
    /* The level is paletted, so a TexSubImage2D with any format is refused, too. */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, blob);
    CHECK(glGetError() != GL_NO_ERROR);

    return ct_done();
}
