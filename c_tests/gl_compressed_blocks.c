/*
 * Block-compressed textures decoded on upload: GL_IMG_texture_compression_pvrtc (4 and
 * 2 bpp, RGB and RGBA), GL_EXT_texture_compression_dxt1, GL_ANGLE_texture_compression_dxt3
 * and _dxt5, and sub-image updates of ETC1 (GL_EXT_compressed_ETC1_RGB8_sub_texture) and
 * S3TC images on 4 × 4 block boundaries. Each texture is drawn 1:1 with NEAREST and
 * REPLACE, so every pixel is a decoded texel. Expected texels use block endpoints (and,
 * for PVRTC, uniform images whose upscale is exact), where the formats fix the value.
 * Every error the uploads can raise is checked.
 *
 * Mesa has no PVRTC: that part runs where the extension is listed (always here).
 * ct:no-diff (Mesa 22.3's GLES 1 lists the S3TC extensions and formats but refuses the
 * formats in glCompressedTexImage2D with GL_INVALID_ENUM: CONFORMANCE.md)
 */
#include "common.h"

static void quad(void)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    static const GLfloat t[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(2, GL_FLOAT, 0, t);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

/* Draws the bound texture over a w × h viewport. */
static void draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    quad();
}

static int has_extension(const char *name)
{
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    return ext != NULL && strstr(ext, name) != NULL;
}

/* One PVRTC word: opaque colors A (5-bit r, g; 4-bit b) and B (5-bit r, g, b), the
 * modulation flag and the 32 modulation bits, as 8 little-endian bytes. */
static void pvrtc_word(GLubyte out[8], unsigned ar, unsigned ag, unsigned ab, unsigned br,
                       unsigned bg, unsigned bb, int m, unsigned long modulation)
{
    unsigned long ca = 0x8000u | ar << 10 | ag << 5 | ab << 1 | (unsigned)m;
    unsigned long cb = 0x8000u | br << 10 | bg << 5 | bb;
    unsigned long words[2];
    int i;
    words[0] = modulation & 0xFFFFFFFFul;
    words[1] = ca | cb << 16;
    for (i = 0; i < 8; ++i)
        out[i] = (GLubyte)(words[i / 4] >> (8 * (i % 4)));
}

static void fill_words(GLubyte *data, int bytes, const GLubyte word[8])
{
    int i;
    for (i = 0; i < bytes; ++i)
        data[i] = word[i % 8];
}

/* A level of `w` × `h` (32 bytes) of PVRTC `format` made of copies of `word`, drawn. */
static void uniform_pvrtc(GLenum format, int w, int h, const GLubyte word[8])
{
    GLubyte data[32];
    fill_words(data, 32, word);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, 32, data);
    draw(w, h);
}

static void pvrtc(void)
{
    GLubyte word[8], data[64];

    /* 8 × 8 at 4 bpp: 2 × 2 words, 32 bytes. A white, B red, every pixel modulated
     * fully to B: red. Weight 3 (01): floor((255·5 + 0·3)/8) = 159 in green and blue. */
    pvrtc_word(word, 31, 31, 15, 31, 0, 0, 0, 0xFFFFFFFFul);
    uniform_pvrtc(GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 8, 8, word);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);
    CHECK_PIXEL(7, 7, 255, 0, 0, 255, 0);
    ct_save("pvrtc4_red");
    pvrtc_word(word, 31, 31, 15, 31, 0, 0, 0, 0x55555555ul);
    uniform_pvrtc(GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 8, 8, word);
    CHECK_PIXEL(3, 4, 255, 159, 159, 255, 0);

    /* Punch-through (flag 1, bits 10): half of A and B, alpha 0; the RGB format keeps
     * alpha 1. */
    pvrtc_word(word, 31, 31, 15, 0, 0, 0, 1, 0xAAAAAAAAul);
    uniform_pvrtc(GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 8, 8, word);
    CHECK_PIXEL(2, 2, 127, 127, 127, 0, 0);
    uniform_pvrtc(GL_COMPRESSED_RGB_PVRTC_4BPPV1_IMG, 8, 8, word);
    CHECK_PIXEL(2, 2, 127, 127, 127, 255, 0);

    /* 2 bpp, 16 × 8, direct modulation: bit 1 of each word's first row selects B for
     * pixel 1 of that row. */
    pvrtc_word(word, 0, 0, 0, 31, 31, 31, 0, 0x2ul);
    uniform_pvrtc(GL_COMPRESSED_RGB_PVRTC_2BPPV1_IMG, 16, 8, word);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(0, 0, 0, 0, 0, 255, 0);
    CHECK_PIXEL(1, 0, 255, 255, 255, 255, 0);
    CHECK_PIXEL(9, 4, 255, 255, 255, 255, 0);
    CHECK_PIXEL(2, 0, 0, 0, 0, 255, 0);
    /* The same words as data for the uploads below (and the 48-byte error case). */
    fill_words(data, 64, word);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_2BPPV1_IMG, 16, 8, 0, 32,
                           data);
    CHECK_GL(GL_NO_ERROR);

    /* A level smaller than its words still takes 2 × 2 of them. */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 1, 1, 0, 32,
                           data);
    CHECK_GL(GL_NO_ERROR);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_2BPPV1_IMG, 2, 2, 0, 32,
                           data);
    CHECK_GL(GL_NO_ERROR);

    /* Errors: sizes not powers of two, a wrong byte count, a border. */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 12, 8, 0, 48,
                           data);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 8, 8, 0, 31,
                           data);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 8, 8, 1, 32,
                           data);
    CHECK_GL(GL_INVALID_VALUE);

    /* Sub-images replace whole levels only. */
    pvrtc_word(word, 31, 31, 15, 0, 0, 31, 0, 0xFFFFFFFFul);
    fill_words(data, 32, word);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG, 8, 8, 0, 32,
                           data);
    pvrtc_word(word, 31, 31, 15, 0, 31, 0, 0, 0xFFFFFFFFul);
    fill_words(data, 32, word);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG,
                              32, data);
    CHECK_GL(GL_NO_ERROR);
    draw(8, 8);
    CHECK_PIXEL(4, 4, 0, 255, 0, 255, 0);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 8, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG,
                              32, data);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_COMPRESSED_RGB_PVRTC_4BPPV1_IMG,
                              32, data);
    CHECK_GL(GL_INVALID_OPERATION); /* not the level's format */
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG,
                              16, data);
    CHECK_GL(GL_INVALID_VALUE);
}

/* A DXT1 color block: endpoints e0, e1 (RGB565) and all sixteen indices `index`. */
static void dxt1_block(GLubyte out[8], unsigned e0, unsigned e1, unsigned index)
{
    int i;
    out[0] = (GLubyte)e0;
    out[1] = (GLubyte)(e0 >> 8);
    out[2] = (GLubyte)e1;
    out[3] = (GLubyte)(e1 >> 8);
    for (i = 4; i < 8; ++i)
        out[i] = (GLubyte)(index * 0x55u);
}

static void s3tc(void)
{
    GLubyte data[64];

    /* DXT1 RGB 8 × 4: a red block and a blue one (four-color mode, index 0 = e0). */
    dxt1_block(data, 0xF800, 0x001F, 0);
    dxt1_block(data + 8, 0x001F, 0x0000, 0);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 4, 0, 16, data);
    CHECK_GL(GL_NO_ERROR);
    draw(8, 4);
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);
    CHECK_PIXEL(3, 3, 255, 0, 0, 255, 0);
    CHECK_PIXEL(4, 0, 0, 0, 255, 255, 0);
    CHECK_PIXEL(7, 3, 0, 0, 255, 255, 0);
    ct_save("dxt1");

    /* Sub-image: the second block green. Offsets on block boundaries; sizes whole blocks
     * or reaching the edge. */
    dxt1_block(data + 16, 0x07E0, 0x0000, 0);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8,
                              data + 16);
    CHECK_GL(GL_NO_ERROR);
    draw(8, 4);
    CHECK_PIXEL(1, 1, 255, 0, 0, 255, 0);
    CHECK_PIXEL(5, 2, 0, 255, 0, 255, 0);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8,
                              data);
    CHECK_GL(GL_INVALID_OPERATION);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 8, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8,
                              data);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE,
                              16, data);
    CHECK_GL(GL_INVALID_OPERATION);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 9,
                              data);
    CHECK_GL(GL_INVALID_VALUE);

    /* RGBA DXT1, three-color mode (e0 <= e1), index 3: transparent black. */
    dxt1_block(data, 0x001F, 0xF800, 3);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4, 0, 8, data);
    CHECK_GL(GL_NO_ERROR);
    glClearColor(1, 1, 1, 1);
    glViewport(0, 0, 4, 4);
    glClear(GL_COLOR_BUFFER_BIT);
    quad();
    CHECK_PIXEL(2, 2, 0, 0, 0, 0, 0);

    /* DXT3: alpha 0xF for texel 0, 0 for texel 1 (rows start at the texture's first row);
     * DXT5: endpoints 255 and 0 with codes 0 and 1. Color white. */
    memset(data, 0, sizeof data);
    data[0] = 0x0F;
    dxt1_block(data + 8, 0xFFFF, 0xFFFF, 0);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT3_ANGLE, 4, 4, 0, 16,
                           data);
    CHECK_GL(GL_NO_ERROR);
    draw(4, 4);
    CHECK_PIXEL(0, 0, 255, 255, 255, 255, 0);
    CHECK_PIXEL(1, 0, 255, 255, 255, 0, 0);
    memset(data, 0, 8);
    data[0] = 255;
    data[1] = 0;
    data[2] = 0x08; /* texel 0: code 0 (a0 = 255), texel 1: code 1 (a1 = 0) */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE, 4, 4, 0, 16,
                           data);
    CHECK_GL(GL_NO_ERROR);
    draw(4, 4);
    CHECK_PIXEL(0, 0, 255, 255, 255, 255, 0);
    CHECK_PIXEL(1, 0, 255, 255, 255, 0, 0);

    /* Sizes: DXT1 takes any size (partial blocks count whole); the ANGLE formats want whole
     * blocks (or 1 and 2), else INVALID_OPERATION; a wrong byte count is INVALID_VALUE. */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 6, 4, 0, 16, data);
    CHECK_GL(GL_NO_ERROR);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE, 2, 2, 0, 16,
                           data);
    CHECK_GL(GL_NO_ERROR);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE, 6, 4, 0, 32,
                           data);
    CHECK_GL(GL_INVALID_OPERATION);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT3_ANGLE, 4, 4, 0, 8,
                           data);
    CHECK_GL(GL_INVALID_VALUE);
}

static void etc1_sub_texture(void)
{
    /* Individual mode blocks, every pixel index 0 (+2): red (R = 0xF in both halves) gives
     * (255, 2, 2), green (2, 255, 2). */
    static const GLubyte red[8] = {0xFF, 0x00, 0x00, 0x00, 0, 0, 0, 0};
    static const GLubyte green[8] = {0x00, 0xFF, 0x00, 0x00, 0, 0, 0, 0};
    GLubyte data[16];
    memcpy(data, red, 8);
    memcpy(data + 8, red, 8);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_ETC1_RGB8_OES, 8, 4, 0, 16, data);
    CHECK_GL(GL_NO_ERROR);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 4, GL_ETC1_RGB8_OES, 8, green);
    CHECK_GL(GL_NO_ERROR);
    draw(8, 4);
    CHECK_PIXEL(1, 1, 255, 2, 2, 255, 0);
    CHECK_PIXEL(6, 3, 2, 255, 2, 255, 0);
    ct_save("etc1_sub");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_ETC1_RGB8_OES, 8, green);
    CHECK_GL(GL_INVALID_OPERATION);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 4, GL_ETC1_RGB8_OES, 7, green);
    CHECK_GL(GL_INVALID_VALUE);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 4, 4, GL_ETC1_RGB8_OES, 8, green);
    CHECK(glGetError() != GL_NO_ERROR); /* level 1 has no image */
}

int main(void)
{
    GLuint tex;
    GLint n = 0, formats[64];
    int i, found = 0;

    ct_init(16, 8);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

    glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &n);
    CHECK(n > 0 && n <= 64);
    if (n > 0 && n <= 64) {
        glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, formats);
        for (i = 0; i < n; ++i)
            found += formats[i] == GL_COMPRESSED_RGB_S3TC_DXT1_EXT ||
                     formats[i] == GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE;
        CHECK(found == 2);
    }

    if (ct_strict())
        CHECK(has_extension("GL_IMG_texture_compression_pvrtc"));
    if (has_extension("GL_IMG_texture_compression_pvrtc"))
        pvrtc();
    CHECK(has_extension("GL_EXT_texture_compression_dxt1"));
    CHECK(has_extension("GL_ANGLE_texture_compression_dxt3"));
    CHECK(has_extension("GL_ANGLE_texture_compression_dxt5"));
    s3tc();
    CHECK(has_extension("GL_EXT_compressed_ETC1_RGB8_sub_texture"));
    etc1_sub_texture();

    glDeleteTextures(1, &tex);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
