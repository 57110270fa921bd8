/*
 * glReadPixels and glPixelStorei: the two allowed format/type pairs (RGBA/UNSIGNED_BYTE and
 * the implementation read format of OES_read_format), GL_PACK_ALIGNMENT padding (bytes past
 * each row's pixels stay untouched), reads of a sub-rectangle, and every error.
 */
#include "common.h"

int main(void)
{
    static const EGLint rgb888[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                    EGL_ALPHA_SIZE, 0, EGL_NONE};
    GLubyte buf[64];
    GLint v = 0, format = 0, type = 0;
    int i;

    ct_init_config(8, 8, rgb888);

    glGetIntegerv(GL_PACK_ALIGNMENT, &v);
    CHECK(v == 4);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &v);
    CHECK(v == 4);

    /* Left half (x < 4) red, right half green. */
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 4, 8);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);

    /* RGBA / UNSIGNED_BYTE of a 3x2 block straddling the halves; alpha reads 255 on a
     * surface without alpha. Rows are 12 bytes, a multiple of every alignment. */
    memset(buf, 0xAB, sizeof buf);
    glReadPixels(2, 3, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, buf);
    CHECK_GL(GL_NO_ERROR);
    for (i = 0; i < 6; ++i) {
        int red = (i % 3) < 2;
        CHECK(buf[4 * i] == (red ? 255 : 0) && buf[4 * i + 1] == (red ? 0 : 255) &&
              buf[4 * i + 2] == 0 && buf[4 * i + 3] == 255);
    }
    CHECK(buf[24] == 0xAB);

    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, &type);
    CHECK_GL(GL_NO_ERROR);
    if (format == GL_RGB && type == GL_UNSIGNED_BYTE) {
        /* 3 pixels of RGB are 9 bytes; alignment 4 pads rows to 12, alignment 1 packs them. */
        memset(buf, 0xAB, sizeof buf);
        glReadPixels(2, 3, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, buf);
        CHECK_GL(GL_NO_ERROR);
        CHECK(buf[0] == 255 && buf[1] == 0 && buf[2] == 0);
        CHECK(buf[6] == 0 && buf[7] == 255 && buf[8] == 0);
        CHECK(buf[9] == 0xAB && buf[10] == 0xAB && buf[11] == 0xAB);
        CHECK(buf[12] == 255 && buf[20] == 0 && buf[21] == 0xAB);

        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        memset(buf, 0xAB, sizeof buf);
        glReadPixels(2, 3, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, buf);
        CHECK(buf[9] == 255 && buf[17] == 0 && buf[18] == 0xAB);

        glPixelStorei(GL_PACK_ALIGNMENT, 8);
        memset(buf, 0xAB, sizeof buf);
        glReadPixels(2, 3, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, buf);
        CHECK(buf[15] == 0xAB && buf[16] == 255 && buf[24] == 0 && buf[25] == 0xAB);
        glPixelStorei(GL_PACK_ALIGNMENT, 2);
        glGetIntegerv(GL_PACK_ALIGNMENT, &v);
        CHECK(v == 2);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        CHECK_GL(GL_NO_ERROR);
    }

    /* A zero-sized read writes nothing and is no error. */
    memset(buf, 0xAB, sizeof buf);
    glReadPixels(0, 0, 0, 5, GL_RGBA, GL_UNSIGNED_BYTE, buf);
    CHECK_GL(GL_NO_ERROR);
    CHECK(buf[0] == 0xAB);

    /* Errors, none of which writes to the buffer. */
    glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf);
    CHECK_GL(GL_INVALID_VALUE);
    glReadPixels(0, 0, 1, -1, GL_RGBA, GL_UNSIGNED_BYTE, buf);
    CHECK_GL(GL_INVALID_VALUE);
    /* Not a pixel format or type of ES 1.1 at all. */
    glReadPixels(0, 0, 1, 1, GL_TEXTURE_2D, GL_UNSIGNED_BYTE, buf);
    CHECK_MESA_DEVIATES(glGetError() == GL_INVALID_ENUM, "raises GL_INVALID_OPERATION");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, buf);
    CHECK_MESA_DEVIATES(glGetError() == GL_INVALID_ENUM, "raises GL_INVALID_OPERATION");
    /* Valid enums, but neither of the two accepted combinations. */
    glReadPixels(0, 0, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, buf);
    CHECK_MESA_DEVIATES(glGetError() == GL_INVALID_OPERATION, "accepts LUMINANCE reads");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, buf);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK_MESA_DEVIATES(buf[0] == 0xAB, "wrote the LUMINANCE read");

    glPixelStorei(GL_PACK_ALIGNMENT, 3);
    CHECK_GL(GL_INVALID_VALUE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 0);
    CHECK_GL(GL_INVALID_VALUE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 16);
    CHECK_GL(GL_INVALID_VALUE);
    glPixelStorei(0x0D02 /* GL_PACK_ROW_LENGTH: desktop GL only */, 0);
    CHECK_GL(GL_INVALID_ENUM);
    glGetIntegerv(GL_PACK_ALIGNMENT, &v);
    CHECK(v == 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &v);
    CHECK(v == 1);
    CHECK_GL(GL_NO_ERROR);
    ct_save("halves");
    return ct_done();
}
