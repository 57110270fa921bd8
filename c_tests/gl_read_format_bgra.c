/*
 * gl_read_format_bgra.c: GL_EXT_read_format_bgra: glReadPixels into BGRA bytes and into
 * the reversed 4444 and 1555 words (blue in the lowest bits), whatever the surface's own
 * read format; the reversed types with any other format are GL_INVALID_OPERATION.
 */
#include "common.h"

#include <stdint.h>

#ifndef GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT
#define GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT 0x8365
#define GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT 0x8366
#endif

int main(void)
{
    GLubyte bytes[4 * 4] = {0};
    uint16_t words[4] = {0};

    ct_init(4, 4);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_read_format_bgra") != NULL);
    /* Red 1, green 0, blue 1/3, alpha 1: exact in 8, 4 and 5 bits (0x55 = 5/15 = 11/31...). */
    glClearColor(1.0f, 0.0f, 1.0f / 3.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    glReadPixels(0, 0, 2, 1, GL_BGRA_EXT, GL_UNSIGNED_BYTE, bytes);
    CHECK_GL(GL_NO_ERROR);
    CHECK(bytes[0] == 85 && bytes[1] == 0 && bytes[2] == 255 && bytes[3] == 255);
    CHECK(bytes[4] == 85 && bytes[6] == 255);

    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT, words);
    CHECK_GL(GL_NO_ERROR);
    /* A in 15..12, R in 11..8, G in 7..4, B in 3..0. */
    CHECK(words[0] == 0xFF05);

    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT, words);
    CHECK_GL(GL_NO_ERROR);
    /* A in 15, R in 14..10, G in 9..5, B in 4..0 (85/255 * 31 rounds to 10). */
    CHECK(words[0] == (1u << 15 | 31u << 10 | 0u << 5 | 10u));

    /* Errors: reversed types need BGRA; BGRA takes no other type. */
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT, words);
    CHECK_GL(GL_INVALID_OPERATION);
    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_UNSIGNED_SHORT_5_6_5, words);
    CHECK_GL(GL_INVALID_OPERATION);
    glReadPixels(0, 0, 1, 1, GL_BGRA_EXT, GL_FLOAT, words);
    CHECK_GL(GL_INVALID_ENUM);
    return ct_done();
}
