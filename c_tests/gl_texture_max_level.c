/*
 * gl_texture_max_level.c: GL_APPLE_texture_max_level: the deepest level mipmapping uses
 * (initially 1000), for sampling and for completeness; negative levels are
 * GL_INVALID_VALUE.
 */
#include "common.h"

#ifndef GL_TEXTURE_MAX_LEVEL_APPLE
#define GL_TEXTURE_MAX_LEVEL_APPLE 0x813D
#endif

static void level(int l, int size, GLubyte r, GLubyte g, GLubyte b)
{
    GLubyte texels[4 * 4 * 4];
    int i;
    for (i = 0; i < size * size; ++i) {
        texels[4 * i] = r;
        texels[4 * i + 1] = g;
        texels[4 * i + 2] = b;
        texels[4 * i + 3] = 255;
    }
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

/* A one-pixel quad over the whole texture: λ = 2, the 1 × 1 level when it may. */
static void draw_minified(void)
{
    static const GLfloat v[] = {-1, -1, -0.75f, -1, -1, -0.75f, -0.75f, -0.75f};
    static const GLfloat st[] = {0, 0, 1, 0, 0, 1, 1, 1};
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

int main(void)
{
    GLuint tex;
    GLint v = 0;

    ct_init(8, 8);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_APPLE_texture_max_level") != NULL);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, &v);
    CHECK(v == 1000);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glClearColor(0, 0, 0, 0);
    glColor4f(1, 1, 1, 1);

    /* Levels 0 and 1 only: incomplete with the default maximum, so texturing is off. */
    level(0, 4, 255, 0, 0);
    level(1, 2, 0, 255, 0);
    draw_minified();
    CHECK_PIXEL(0, 0, 255, 255, 255, 255, 0);
    /* Complete once the chain may stop at level 1, which a minified quad then samples. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, 1);
    draw_minified();
    CHECK_PIXEL(0, 0, 0, 255, 0, 255, 0);
    /* With level 2 too and the maximum back up, level 2 is sampled. */
    level(2, 1, 0, 0, 255);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, 1000.0f);
    draw_minified();
    CHECK_PIXEL(0, 0, 0, 0, 255, 255, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, 0);
    draw_minified();
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, &v);
    CHECK(v == 0);
    CHECK_GL(GL_NO_ERROR);

    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, -1);
    CHECK_GL(GL_INVALID_VALUE);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL_APPLE, &v);
    CHECK(v == 0);
    glDeleteTextures(1, &tex);
    return ct_done();
}
