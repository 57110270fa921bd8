/*
 * gl_read_format_bgra.c: GL_EXT_read_format_bgra: glReadPixels into BGRA bytes whatever
 * the surface's own read format; the extension's reversed 16-bit types are known names
 * (GL_INVALID_OPERATION, not GL_INVALID_ENUM) but no surface here reads in them.
 */
#include "common.h"

#ifndef GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT
#define GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT 0x8365
#define GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT 0x8366
#endif

int main(void)
{
    GLubyte bytes[4 * 4] = {0};
    GLint format = 0, type = 0;

    ct_init(4, 4);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_read_format_bgra") != NULL);
    /* Red 1, green 0, blue 1/3, alpha 1: exact in 8 bits (85). */
    glClearColor(1.0f, 0.0f, 1.0f / 3.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    glReadPixels(0, 0, 2, 1, GL_BGRA_EXT, GL_UNSIGNED_BYTE, bytes);
    CHECK_GL(GL_NO_ERROR);
    CHECK(bytes[0] == 85 && bytes[1] == 0 && bytes[2] == 255 && bytes[3] == 255);
    CHECK(bytes[4] == 85 && bytes[6] == 255);

    /* The reversed types: only as the implementation read format, which is RGBA bytes here
     * (Mesa names BGRA bytes: either way, not a reversed type). */
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, &type);
    CHECK(type == GL_UNSIGNED_BYTE);
    CHECK(!ct_strict() || format == GL_RGBA);
    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT, bytes);
    CHECK_GL(GL_INVALID_OPERATION);
    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT, bytes);
    CHECK_GL(GL_INVALID_OPERATION);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT, bytes);
    CHECK_GL(GL_INVALID_OPERATION);
    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_SHORT_5_6_5, bytes);
    CHECK_GL(GL_INVALID_OPERATION);
    /* GL_FLOAT is no pixel type of ES 1.1 at all: GL_INVALID_ENUM. */
    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_FLOAT, bytes);
    CHECK_MESA_DEVIATES(glGetError() == GL_INVALID_ENUM, "raises GL_INVALID_OPERATION");
    CHECK(bytes[0] == 85); /* no failed read wrote anything */
    return ct_done();
}
