/*
 * Clearing an RGB565 surface: the clear color is converted to 5/6/5 bits (round to nearest)
 * and read back as RGBA/UNSIGNED_BYTE, each component expanded to 8 bits (c x 255 / (2^n - 1),
 * rounded); alpha reads as 255. 0.4 -> 12/31 -> 99 and 25/63 -> 101. Also the implementation
 * read format of OES_read_format for this surface and a 5_6_5 read.
 */
#include "common.h"

int main(void)
{
    static const EGLint rgb565[] = {EGL_RED_SIZE, 5, EGL_GREEN_SIZE, 6, EGL_BLUE_SIZE, 5,
                                    EGL_ALPHA_SIZE, 0, EGL_BUFFER_SIZE, 16, EGL_NONE};
    GLint v[1], format = 0, type = 0;
    GLushort p565[4] = {0, 0, 0, 0};

    ct_init_config(16, 16, rgb565);
    glGetIntegerv(GL_RED_BITS, v);
    CHECK(v[0] == 5);
    glGetIntegerv(GL_GREEN_BITS, v);
    CHECK(v[0] == 6);
    glGetIntegerv(GL_ALPHA_BITS, v);
    CHECK(v[0] == 0);

    glClearColor(0.4f, 0.4f, 1, 0.2f);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(3, 3, 99, 101, 255, 255, 0);

    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, &type);
    CHECK_GL(GL_NO_ERROR);
    if (format == GL_RGB && type == GL_UNSIGNED_SHORT_5_6_5) {
        glReadPixels(0, 0, 2, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565);
        CHECK_GL(GL_NO_ERROR);
        CHECK(p565[0] == ((12 << 11) | (25 << 5) | 31));
        CHECK(p565[1] == p565[0]);
        CHECK(p565[2] == 0);
    }
    ct_save("clear565");
    return ct_done();
}
