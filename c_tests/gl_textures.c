/* Texture objects: names, binding, parameters, TexImage2D / TexSubImage2D validation. */
#include "common.h"

static GLint get_int(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

int main(void)
{
    GLuint tex[3] = {0, 0, 0};
    GLint v = 0, rect[4] = {0, 0, 0, 0};
    GLfloat f = 0, frect[4] = {0, 0, 0, 0};
    GLfixed x = 0, xrect[4] = {0, 0, 0, 0};
    static GLubyte pixels[64 * 64 * 4];
    static const GLint crop[4] = {1, 2, 3, 4};
    static const GLfloat cropf[4] = {5, 6, 7, 8};
    static const GLfixed cropx[4] = {9 << 16, 10 << 16, 11 << 16, 12 << 16};

    ct_init(16, 16);

    /* Names. */
    CHECK(get_int(GL_TEXTURE_BINDING_2D) == 0);
    CHECK(get_int(GL_MAX_TEXTURE_SIZE) >= 64);
    glGenTextures(-1, tex);
    CHECK_GL(GL_INVALID_VALUE);
    glGenTextures(3, tex);
    CHECK_GL(GL_NO_ERROR);
    CHECK(tex[0] != 0 && tex[1] != 0 && tex[2] != 0 && tex[0] != tex[1] && tex[1] != tex[2]);
    CHECK(!glIsTexture(tex[0]));
    CHECK(!glIsTexture(0));
    glBindTexture(GL_TEXTURE_2D + 1, tex[0]);
    CHECK_GL(GL_INVALID_ENUM);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsTexture(tex[0]));
    CHECK(get_int(GL_TEXTURE_BINDING_2D) == (GLint)tex[0]);
    /* Binding an unused name creates it. */
    glBindTexture(GL_TEXTURE_2D, 1234);
    CHECK(glIsTexture(1234));
    glBindTexture(GL_TEXTURE_2D, tex[0]);

    /* Per-unit bindings; deleting unbinds from every unit. */
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    CHECK(get_int(GL_TEXTURE_BINDING_2D) == (GLint)tex[0]);
    glActiveTexture(GL_TEXTURE0);
    glDeleteTextures(-1, tex);
    CHECK_GL(GL_INVALID_VALUE);
    glDeleteTextures(1, tex);
    CHECK_GL(GL_NO_ERROR);
    CHECK(!glIsTexture(tex[0]));
    CHECK(get_int(GL_TEXTURE_BINDING_2D) == 0);
    glActiveTexture(GL_TEXTURE1);
    CHECK(get_int(GL_TEXTURE_BINDING_2D) == 0);
    glActiveTexture(GL_TEXTURE0);
    glDeleteTextures(1, &tex[2]); /* never bound: fine */
    CHECK_GL(GL_NO_ERROR);

    /* Parameters: defaults and round trips through every getter. */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
    CHECK(v == GL_NEAREST_MIPMAP_LINEAR);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &v);
    CHECK(v == GL_LINEAR);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &v);
    CHECK(v == GL_REPEAT);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &v);
    CHECK(v == GL_REPEAT);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &v);
    CHECK(v == GL_FALSE);
    CHECK_GL(GL_NO_ERROR);

    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &f);
    CHECK(f == (GLfloat)GL_LINEAR_MIPMAP_NEAREST);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLfloat)GL_NEAREST);
    glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &x);
    CHECK(x == GL_NEAREST);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &v);
    CHECK(v == GL_CLAMP_TO_EDGE);
    v = GL_CLAMP_TO_EDGE;
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &v);
    f = (GLfloat)GL_TRUE;
    glTexParameterfv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &f);
    x = GL_LINEAR;
    glTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &x);
    CHECK_GL(GL_NO_ERROR);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &v);
    CHECK(v == GL_CLAMP_TO_EDGE);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &v);
    CHECK(v == GL_TRUE);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
    CHECK(v == GL_LINEAR);

    /* Parameter errors leave state alone. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE + 1000);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_NEAREST);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameteri(GL_TEXTURE_2D + 1, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameterf(GL_TEXTURE_2D + 1, GL_TEXTURE_MIN_FILTER, (GLfloat)GL_NEAREST);
    CHECK_GL(GL_INVALID_ENUM);
    glTexParameterx(GL_TEXTURE_2D, 0, GL_NEAREST);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexParameteriv(GL_TEXTURE_2D + 1, GL_TEXTURE_MIN_FILTER, &v);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, &f);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexParameterxv(GL_TEXTURE_2D, 0, &x);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &v);
    CHECK(v == GL_CLAMP_TO_EDGE);

    /* OES_draw_texture's crop rectangle, through the vector forms. */
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, crop);
    CHECK_GL(GL_NO_ERROR);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, rect);
    CHECK(rect[0] == 1 && rect[1] == 2 && rect[2] == 3 && rect[3] == 4);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, cropf);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, frect);
    CHECK(frect[0] == 5 && frect[1] == 6 && frect[2] == 7 && frect[3] == 8);
    glTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, cropx);
    glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, xrect);
    CHECK(xrect[0] == 9 << 16 && xrect[1] == 10 << 16 && xrect[2] == 11 << 16 &&
          xrect[3] == 12 << 16);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, rect);
    CHECK(rect[0] == 9 && rect[3] == 12);
    CHECK_GL(GL_NO_ERROR);

    /* TexImage2D: every error. */
    glTexImage2D(GL_TEXTURE_2D + 1, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_ENUM);
    /* An unknown format is INVALID_ENUM, but it also differs from internalformat
     * (INVALID_OPERATION) and Mesa reports INVALID_VALUE: any error will do. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, pixels);
    CHECK(glGetError() != GL_NO_ERROR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, 0x1234, pixels);
    CHECK(glGetError() != GL_NO_ERROR); /* INVALID_ENUM here; Mesa says INVALID_VALUE */
    glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexImage2D(GL_TEXTURE_2D, 30, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, -4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, get_int(GL_MAX_TEXTURE_SIZE) * 2, 1, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, NULL);
    CHECK_GL(GL_INVALID_VALUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    /* ES 1.1 requires powers of two (Mesa exposes OES_texture_npot). */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    if (!strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_texture_npot"))
        CHECK_GL(GL_INVALID_VALUE);
    else
        (void)glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_OPERATION);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, pixels);
    CHECK_GL(GL_INVALID_OPERATION);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, pixels);
    CHECK_GL(GL_INVALID_OPERATION);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 4, 0, GL_LUMINANCE,
                 GL_UNSIGNED_SHORT_5_5_5_1, pixels);
    CHECK_GL(GL_INVALID_OPERATION);

    /* Every valid format / type pair, null pixels allowed. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 4, 4, 0, GL_ALPHA, GL_UNSIGNED_BYTE, pixels);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, NULL);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 4, 4, 0, GL_LUMINANCE_ALPHA,
                 GL_UNSIGNED_BYTE, pixels);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, pixels);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, pixels);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, pixels);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    /* Odd row lengths with the unpack alignment. */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    CHECK_GL(GL_NO_ERROR);

    /* TexSubImage2D. */
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_OPERATION); /* no level 0 in the default texture yet */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_OPERATION); /* no level 1 */
    glTexSubImage2D(GL_TEXTURE_2D + 1, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_ENUM);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, 0x1234, pixels);
    CHECK_GL(GL_INVALID_ENUM);
    glTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 7, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 3, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, pixels);
    CHECK_GL(GL_INVALID_OPERATION);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_OPERATION); /* format differs from the level's */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 6, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, pixels);
    CHECK_GL(GL_NO_ERROR);

    /* GENERATE_MIPMAP makes the chain, so sub-images of level 2 work. */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, pixels);
    glTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_NO_ERROR);
    glTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 2, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, pixels);
    CHECK_GL(GL_INVALID_VALUE);

    return ct_done();
}
