/*
 * GL_OES_required_internalformat: glTexImage2D and glCopyTexImage2D take sized internal
 * formats, with the client formats and types of the extension's table (else
 * GL_INVALID_OPERATION), and store texels at the format's precision (sub-image updates
 * too). Values a format represents exactly are checked everywhere; how a value between
 * two steps rounds is left to the implementation by the extension, so that check (to the
 * nearest step) is made only here.
 */
#include "common.h"

/* (99, 150, 197) stored as RGB565 and read back: blue 197 is 24 of 31, which is 197.4 as
 * a color and 197 in the 8-bit surface (ES 1.1 §2.14.9 and §3.6.2's conversions). Mesa
 * widens 5 bits by repeating the high bits (198), one step off. */
static void check_197(int x, int y)
{
    GLubyte p[4];
    ct_read(x, y, p);
    CHECK(p[0] == 99 && p[1] == 150 && p[3] == 255);
    CHECK_MESA_DEVIATES(p[2] == 197, "Mesa widens 5-bit blue 24 to 198 by bit replication");
}

static void quad(void)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    static const GLfloat t[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(2, GL_FLOAT, 0, t);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void tex(GLint internal, GLenum format, GLenum type, const void *pixels)
{
    glTexImage2D(GL_TEXTURE_2D, 0, internal, 2, 1, 0, format, type, pixels);
}

int main(void)
{
    /* Texel 0 exactly representable in 5/6/5 bits (99 = 12 of 31, 150 = 37 of 63, 197 = 24
     * of 31); texel 1 between steps: 100 → 12 → 99, 152 → 38 → 154, 200 → 24 → 197. */
    static const GLubyte rgb[6] = {99, 150, 197, 100, 152, 200};
    static const GLubyte rgba[8] = {0x88, 0x44, 0xCC, 0xFF, 0x80, 0x40, 0xC0, 0x70};
    static const GLubyte la[4] = {0x77, 0xAA, 0x70, 0xA0};
    static const GLushort packed4444[2] = {0x8F4F, 0x1234};
    int strict;
    GLuint name;

    ct_init(2, 1);
    strict = ct_strict();
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_required_internalformat") !=
          NULL);
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    /* RGB565 from unsigned bytes. */
    tex(GL_RGB565_OES, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    CHECK_GL(GL_NO_ERROR);
    quad();
    check_197(0, 0);
    if (strict)
        CHECK_PIXEL(1, 0, 99, 154, 197, 255, 0);

    /* RGBA4 from bytes and from its packed type; 0x88 0x44 0xCC 0xFF are whole steps. */
    tex(GL_RGBA4_OES, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    CHECK_GL(GL_NO_ERROR);
    quad();
    CHECK_PIXEL(0, 0, 0x88, 0x44, 0xCC, 0xFF, 0);
    if (strict)
        CHECK_PIXEL(1, 0, 0x88, 0x44, 0xBB, 0x77, 0); /* 0xC0 → 11 of 15, 0x70 → 7 */
    tex(GL_RGBA4_OES, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, packed4444);
    CHECK_GL(GL_NO_ERROR);
    quad();
    CHECK_PIXEL(0, 0, 0x88, 0xFF, 0x44, 0xFF, 0);

    /* RGB5_A1: one bit of alpha; a sub-image update is stored at the same precision. */
    tex(GL_RGB5_A1_OES, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    CHECK_GL(GL_NO_ERROR);
    {
        static const GLubyte sub[4] = {0xFF, 0x00, 0xFF, 0xE0};
        glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, sub);
        CHECK_GL(GL_NO_ERROR);
    }
    quad();
    CHECK_PIXEL(1, 0, 0xFF, 0x00, 0xFF, 0xFF, 0);
    ct_save("rgb5_a1");

    /* Luminance-alpha at 4 bits: 0x77 and 0xAA are whole steps. */
    tex(GL_LUMINANCE4_ALPHA4_OES, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    CHECK_GL(GL_NO_ERROR);
    quad();
    CHECK_PIXEL(0, 0, 0x77, 0x77, 0x77, 0xAA, 0);
    if (strict)
        CHECK_PIXEL(1, 0, 0x77, 0x77, 0x77, 0x99, 0); /* 0x70 → 7 of 15, 0xA0 → 9 */

    /* The 8-bit formats keep every value. */
    tex(GL_RGB8_OES, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    quad();
    CHECK_PIXEL(1, 0, 100, 152, 200, 255, 0);
    tex(GL_RGBA8_OES, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    quad();
    CHECK_PIXEL(1, 0, 0x80, 0x40, 0xC0, 0x70, 0);
    tex(GL_LUMINANCE8_ALPHA8_OES, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    quad();
    CHECK_PIXEL(1, 0, 0x70, 0x70, 0x70, 0xA0, 0);
    tex(GL_LUMINANCE8_OES, GL_LUMINANCE, GL_UNSIGNED_BYTE, la);
    quad();
    CHECK_PIXEL(1, 0, 0xAA, 0xAA, 0xAA, 0xFF, 0);
    tex(GL_ALPHA8_OES, GL_ALPHA, GL_UNSIGNED_BYTE, la);
    CHECK_GL(GL_NO_ERROR);

    /* Combinations outside the table, and unknown formats. */
    tex(GL_RGB565_OES, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, packed4444);
    CHECK_GL(GL_INVALID_OPERATION);
    tex(GL_RGB8_OES, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    CHECK_GL(GL_INVALID_OPERATION);
    tex(GL_RGBA8_OES, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, packed4444);
    CHECK_GL(GL_INVALID_OPERATION);
    tex(GL_LUMINANCE8_OES, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    CHECK_GL(GL_INVALID_OPERATION);
    tex(0x1234, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    CHECK_GL(GL_INVALID_VALUE);

    /* Copies take sized formats too: a cleared color of whole 5/6/5 steps comes back. */
    glClearColor(99 / 255.0f, 150 / 255.0f, 197 / 255.0f, 1);
    glDisable(GL_TEXTURE_2D);
    glClear(GL_COLOR_BUFFER_BIT);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB565_OES, 0, 0, 2, 1, 0);
    CHECK_GL(GL_NO_ERROR);
    glEnable(GL_TEXTURE_2D);
    glClearColor(0, 0, 0, 0);
    quad();
    check_197(0, 0);

    glDeleteTextures(1, &name);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
