/* CopyTexImage2D / CopyTexSubImage2D: errors, format compatibility with the read surface,
 * and that pending rendering lands before the copy. */
#include "common.h"

int main(void)
{
    static const EGLint rgb565[] = {EGL_RED_SIZE, 5, EGL_GREEN_SIZE, 6, EGL_BLUE_SIZE, 5,
                                    EGL_ALPHA_SIZE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT,
                                    EGL_NONE};
    EGLConfig config = 0, configs[64];
    EGLint count = 0, alpha = -1;
    EGLSurface rgb_surface = EGL_NO_SURFACE;
    EGLint pb[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
    GLuint tex = 0;

    ct_init(16, 16); /* RGBA8888 */
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);

    /* Rendering issued before the copy is what gets copied (checked by copying back over a
     * cleared texture and reading it through TexSubImage is not possible in ES 1.1, so the
     * copy must simply succeed after a clear). */
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 8, 8, 0);
    CHECK_GL(GL_NO_ERROR);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 0, 0, 8, 8, 0);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 8, 8, 0);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 0, 0, 8, 8, 0);
    glCopyTexImage2D(GL_TEXTURE_2D, 1, GL_RGB, 4, 4, 4, 4, 0);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, -4, 16, 16, 0); /* partly outside */
    CHECK_GL(GL_NO_ERROR);

    glCopyTexImage2D(GL_TEXTURE_2D + 1, 0, GL_RGBA, 0, 0, 8, 8, 0);
    CHECK_GL(GL_INVALID_ENUM);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 8, 8, 0);
    CHECK(glGetError() != GL_NO_ERROR); /* INVALID_ENUM here; GL 1.x said INVALID_VALUE */
    glCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 0, 0, 8, 8, 0);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -8, 8, 0);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 8, 8, 1);
    CHECK_GL(GL_INVALID_VALUE);

    /* Sub-image copies. */
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 8, 4, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 1, 0, 0, 6, 3);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 0, 0, 0, 0);
    CHECK_GL(GL_NO_ERROR);
    glCopyTexSubImage2D(GL_TEXTURE_2D + 1, 0, 0, 0, 0, 0, 1, 1);
    CHECK_GL(GL_INVALID_ENUM);
    glCopyTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 0, 0, 1, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 0, 5, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 2, 0, 0, 1, 3);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 0, 0, 1, 1);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 0, 0, 1, 1);
    CHECK_GL(GL_INVALID_OPERATION); /* no level 3 */

    /* An RGB surface has no alpha to copy. */
    if (eglChooseConfig(ct.display, rgb565, configs, 64, &count)) {
        EGLint i;
        for (i = 0; i < count && rgb_surface == EGL_NO_SURFACE; ++i) {
            EGLint type = 0;
            config = configs[i];
            if (eglGetConfigAttrib(ct.display, config, EGL_ALPHA_SIZE, &alpha) && alpha == 0 &&
                eglGetConfigAttrib(ct.display, config, EGL_SURFACE_TYPE, &type) &&
                (type & EGL_PBUFFER_BIT))
                rgb_surface = eglCreatePbufferSurface(ct.display, config, pb);
        }
    }
    /* Mesa's surfaceless platform has no alpha-less config; this library must. */
    if (ct_strict())
        CHECK(rgb_surface != EGL_NO_SURFACE);
    if (rgb_surface != EGL_NO_SURFACE) {
        EGLContext rgb_context = eglCreateContext(ct.display, config, ct.context, NULL);
        CHECK(rgb_context != EGL_NO_CONTEXT);
        CHECK(eglMakeCurrent(ct.display, rgb_surface, rgb_surface, rgb_context));
        glBindTexture(GL_TEXTURE_2D, tex);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 4, 4, 0);
        CHECK_GL(GL_NO_ERROR);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 0, 0, 4, 4, 0);
        CHECK_GL(GL_INVALID_OPERATION);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
        CHECK_GL(GL_INVALID_OPERATION);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 0, 0, 4, 4, 0);
        CHECK_GL(GL_INVALID_OPERATION);
        /* The level is LUMINANCE: compatible for sub-image copies. */
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
        CHECK_GL(GL_NO_ERROR);
        CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
        glBindTexture(GL_TEXTURE_2D, tex);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
        CHECK_GL(GL_NO_ERROR);
        CHECK(eglMakeCurrent(ct.display, rgb_surface, rgb_surface, rgb_context));
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
        CHECK_GL(GL_INVALID_OPERATION); /* RGBA level, RGB buffer */
        CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
        eglDestroyContext(ct.display, rgb_context);
        eglDestroySurface(ct.display, rgb_surface);
    }

    return ct_done();
}
