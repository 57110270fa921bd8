/*
 * GL_OES_texture_npot (and GL_APPLE_texture_2D_limited_npot, which it contains): textures
 * of any size. Sampled with NEAREST from negative to positive coordinates, so every
 * pixel's texel is fixed by the wrap rules (REPEAT and MIRRORED_REPEAT by the Euclidean
 * remainder, CLAMP_TO_EDGE); mipmap levels halve with the floor (⌊w / 2^l⌋, at least 1)
 * for completeness; generated chains; LINEAR across the REPEAT seam; the uploads that
 * accept any size now (TexImage, CopyTexImage, paletted and ETC1) and the size errors
 * that remain.
 */
#include "common.h"

enum { TW = 3, TH = 5, VW = 12, VH = 10 };

/* Through eglGetProcAddress (Mesa exports extension functions only that way). */
static PFNGLGENERATEMIPMAPOESPROC glGenerateMipmapOES;

static GLubyte texel(int i, int j, int c)
{
    static const GLubyte base[4] = {20, 10, 200, 255};
    return c == 0 ? base[0] + 40 * i : c == 1 ? base[1] + 40 * j : base[c];
}

static void quad(GLfloat s0, GLfloat t0, GLfloat s1, GLfloat t1)
{
    const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    const GLfloat t[8] = {s0, t0, s1, t0, s1, t1, s0, t1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(2, GL_FLOAT, 0, t);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

static int euclid(int i, int n)
{
    int m = i % n;
    return m < 0 ? m + n : m;
}

static int wrap(GLenum mode, int i, int n)
{
    int m;
    switch (mode) {
    case GL_REPEAT:
        return euclid(i, n);
    case GL_MIRRORED_REPEAT_OES:
        m = euclid(i, 2 * n);
        return m >= n ? 2 * n - 1 - m : m;
    default:
        return i < 0 ? 0 : i >= n ? n - 1 : i;
    }
}

/* Texture coordinates -1 .. 1 over the viewport: pixel (x, y) samples u = (x + ½)/2 − 3,
 * v = y + ½ − 5, a quarter texel or more from any texel edge. */
static void check_wrap(GLenum mode)
{
    GLubyte px[VW * VH * 4];
    int x, y, c, bad = 0;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)mode);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)mode);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(-1, -1, 1, 1);
    glReadPixels(0, 0, VW, VH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (y = 0; y < VH; ++y)
        for (x = 0; x < VW; ++x) {
            int i = wrap(mode, x / 2 - 3, TW), j = wrap(mode, y - 5, TH);
            for (c = 0; c < 4; ++c)
                if (px[(y * VW + x) * 4 + c] != texel(i, j, c)) {
                    if (bad++ < 4)
                        fprintf(stderr, "wrap 0x%04X: pixel (%d, %d) channel %d is %d, texel "
                                        "(%d, %d) has %d\n",
                                (unsigned)mode, x, y, c, px[(y * VW + x) * 4 + c], i, j,
                                texel(i, j, c));
                }
        }
    CHECK(bad == 0);
}

static void solid_level(int level, int w, int h, GLubyte r, GLubyte g, GLubyte b)
{
    GLubyte px[8 * 8 * 4];
    int k;
    for (k = 0; k < w * h; ++k) {
        px[k * 4] = r;
        px[k * 4 + 1] = g;
        px[k * 4 + 2] = b;
        px[k * 4 + 3] = 255;
    }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
}

int main(void)
{
    GLubyte img[TW * TH * 4];
    GLubyte palette4[16 * 3 + 5];
    GLubyte etc1[16];
    GLuint tex[3];
    int i, j, c;
    GLenum e;
    const char *ext;

    ct_init(VW, VH);
    glGenerateMipmapOES = (PFNGLGENERATEMIPMAPOESPROC)eglGetProcAddress("glGenerateMipmapOES");
    CHECK(glGenerateMipmapOES != NULL);
    if (glGenerateMipmapOES == NULL)
        return ct_done();
    ext = (const char *)glGetString(GL_EXTENSIONS);
    CHECK(ext != NULL && strstr(ext, "GL_OES_texture_npot") != NULL);
    if (ct_strict())
        CHECK(strstr(ext, "GL_APPLE_texture_2D_limited_npot") != NULL);

    for (j = 0; j < TH; ++j)
        for (i = 0; i < TW; ++i)
            for (c = 0; c < 4; ++c)
                img[(j * TW + i) * 4 + c] = texel(i, j, c);
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    CHECK_GL(GL_NO_ERROR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0, 0, 0, 0);

    check_wrap(GL_REPEAT);
    ct_save("repeat");
    check_wrap(GL_MIRRORED_REPEAT_OES);
    ct_save("mirrored");
    check_wrap(GL_CLAMP_TO_EDGE);
    CHECK_GL(GL_NO_ERROR);

    /* LINEAR across the REPEAT seam of a 3 × 1 texture (red 0, 90, 180), 6 pixels over
     * s in 0 .. 1, so pixel x samples u = x/2 − ¼. Pixel 0: texels 2 and 0 (wrapped) with
     * weight ¾ on texel 0, 45. Pixel 5: texels 2 and 0 (wrapped) with weight ¼ on texel 0,
     * 135. Both exact in 8-bit weights too; 1 step for the implementation's rounding. */
    {
        static const GLubyte row[3 * 4] = {0, 0, 0, 255, 90, 0, 0, 255, 180, 0, 0, 255};
        glViewport(0, 0, 6, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glClear(GL_COLOR_BUFFER_BIT);
        quad(0, 0, 1, 1);
        CHECK_PIXEL(0, 0, 45, 0, 0, 255, 1);
        CHECK_PIXEL(5, 0, 135, 0, 0, 255, 1);
        glViewport(0, 0, VW, VH);
        CHECK_GL(GL_NO_ERROR);
    }

    /* Mipmap completeness with the floor: 5 × 3, then 2 × 1, then 1 × 1. Texture
     * coordinates 0 .. 32 put λ past the last level, so level 2 (blue) is sampled. */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    solid_level(0, 5, 3, 255, 0, 0);
    solid_level(1, 2, 1, 0, 255, 0);
    solid_level(2, 1, 1, 0, 0, 255);
    CHECK_GL(GL_NO_ERROR);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 32, 32);
    CHECK_PIXEL(5, 5, 0, 0, 255, 255, 0);
    /* Level 1 of 3 × 1 is not ⌊5/2⌋ wide: incomplete, so the unit is disabled and the
     * primary color (white) shows. */
    solid_level(1, 3, 1, 0, 255, 0);
    glColor4f(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 32, 32);
    CHECK_PIXEL(5, 5, 255, 255, 255, 255, 0);
    /* A generated chain of the red base is complete again and red at every level. */
    glGenerateMipmapOES(GL_TEXTURE_2D);
    CHECK_GL(GL_NO_ERROR);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 32, 32);
    CHECK_PIXEL(5, 5, 255, 0, 0, 255, 0);
    /* GL_GENERATE_MIPMAP on a 7 × 3 upload: trilinear over the chain gives its color. */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    solid_level(0, 7, 3, 30, 60, 90);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 5, 5);
    CHECK_PIXEL(6, 4, 30, 60, 90, 255, 0);
    CHECK_GL(GL_NO_ERROR);

    /* Every upload takes any size; the size limits themselves remain. */
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 5, 3, 0);
    CHECK_GL(GL_NO_ERROR);
    memset(palette4, 0, sizeof palette4); /* 16 RGB8 entries, then ⌈3·3/2⌉ index bytes */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGB8_OES, 3, 3, 0,
                           (GLsizei)sizeof palette4, palette4);
    e = glGetError();
    CHECK_MESA_DEVIATES(e == GL_NO_ERROR, "Mesa: GL_OUT_OF_MEMORY for a 3 x 3 paletted image");
    memset(etc1, 0, sizeof etc1); /* 3 × 5: one block across, two down */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_ETC1_RGB8_OES, 3, 5, 0, (GLsizei)sizeof etc1,
                           etc1);
    e = glGetError();
    CHECK_MESA_DEVIATES(e == GL_NO_ERROR, "Mesa: GL_OUT_OF_MEMORY for a 3 x 5 ETC1 image");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    CHECK_GL(GL_INVALID_VALUE);
    if (ct_strict()) {
        /* Past the largest texture (2048 here), and past level 1's 1024. */
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2049, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        CHECK_GL(GL_INVALID_VALUE);
        glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 1025, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        CHECK_GL(GL_INVALID_VALUE);
    }
    glDeleteTextures(3, tex);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
