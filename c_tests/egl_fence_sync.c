/*
 * EGL 1.5 fence syncs and EGL_KHR_fence_sync / EGL_KHR_wait_sync (with GL_OES_EGL_sync): a
 * fence after drawing signals once the drawing is complete (a wait returns
 * EGL_CONDITION_SATISFIED and the pixels are there; the status then reads EGL_SIGNALED);
 * its type and condition; every error of create, wait, query and destroy in both forms.
 */
#include "common.h"
#include <EGL/eglext.h>

static PFNEGLCREATESYNCPROC create_sync;
static PFNEGLDESTROYSYNCPROC destroy_sync;
static PFNEGLCLIENTWAITSYNCPROC client_wait_sync;
static PFNEGLGETSYNCATTRIBPROC get_sync_attrib;
static PFNEGLWAITSYNCPROC wait_sync;
static PFNEGLCREATESYNCKHRPROC create_sync_khr;
static PFNEGLDESTROYSYNCKHRPROC destroy_sync_khr;
static PFNEGLCLIENTWAITSYNCKHRPROC client_wait_sync_khr;
static PFNEGLGETSYNCATTRIBKHRPROC get_sync_attrib_khr;
static PFNEGLWAITSYNCKHRPROC wait_sync_khr;

static void draw_red(void)
{
    static const GLfloat tri[6] = {-1, -1, 3, -1, -1, 3};
    glColor4f(1, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

static void core_fences(void)
{
    EGLAttrib v = 0;
    EGLSync s;
    static const EGLAttrib bad_attribs[] = {EGL_SYNC_CONDITION, EGL_SYNC_PRIOR_COMMANDS_COMPLETE,
                                            EGL_NONE};
    draw_red();
    s = create_sync(ct.display, EGL_SYNC_FENCE, NULL);
    CHECK(s != EGL_NO_SYNC);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(get_sync_attrib(ct.display, s, EGL_SYNC_TYPE, &v) && v == EGL_SYNC_FENCE);
    CHECK(get_sync_attrib(ct.display, s, EGL_SYNC_CONDITION, &v) &&
          v == EGL_SYNC_PRIOR_COMMANDS_COMPLETE);
    CHECK(client_wait_sync(ct.display, s, EGL_SYNC_FLUSH_COMMANDS_BIT, EGL_FOREVER) ==
          EGL_CONDITION_SATISFIED);
    CHECK(get_sync_attrib(ct.display, s, EGL_SYNC_STATUS, &v) && v == EGL_SIGNALED);
    CHECK_PIXEL(4, 4, 255, 0, 0, 255, 0);
    /* A signaled fence satisfies any later wait at once. */
    CHECK(client_wait_sync(ct.display, s, 0, 0) == EGL_CONDITION_SATISFIED);
    CHECK(wait_sync(ct.display, s, 0));
    CHECK_EGL(EGL_SUCCESS);

    /* Errors. */
    CHECK(get_sync_attrib(ct.display, s, EGL_WIDTH, &v) == EGL_FALSE);
    CHECK_EGL(EGL_BAD_ATTRIBUTE);
    CHECK(!wait_sync(ct.display, s, 1));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(create_sync(ct.display, EGL_SYNC_FENCE, bad_attribs) == EGL_NO_SYNC);
    CHECK_EGL(EGL_BAD_ATTRIBUTE);
    CHECK(create_sync(ct.display, 0x3333, NULL) == EGL_NO_SYNC);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(create_sync(EGL_NO_DISPLAY, EGL_SYNC_FENCE, NULL) == EGL_NO_SYNC);
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(destroy_sync(ct.display, s));
    CHECK_EGL(EGL_SUCCESS);
    /* The handle is gone. */
    CHECK(!destroy_sync(ct.display, s));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(client_wait_sync(ct.display, s, 0, 0) == EGL_FALSE);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!get_sync_attrib(ct.display, s, EGL_SYNC_STATUS, &v));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!wait_sync(ct.display, s, 0));
    CHECK_EGL(EGL_BAD_PARAMETER);

    /* No current context: nothing to put a fence after. */
    CHECK(eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(create_sync(ct.display, EGL_SYNC_FENCE, NULL) == EGL_NO_SYNC);
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
}

static void khr_fences(void)
{
    EGLint v = 0;
    EGLSyncKHR s;
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    s = create_sync_khr(ct.display, EGL_SYNC_FENCE_KHR, NULL);
    CHECK(s != EGL_NO_SYNC_KHR);
    CHECK(get_sync_attrib_khr(ct.display, s, EGL_SYNC_TYPE_KHR, &v) && v == EGL_SYNC_FENCE_KHR);
    CHECK(wait_sync_khr(ct.display, s, 0) == EGL_TRUE);
    CHECK(client_wait_sync_khr(ct.display, s, 0, EGL_FOREVER_KHR) ==
          EGL_CONDITION_SATISFIED_KHR);
    CHECK(get_sync_attrib_khr(ct.display, s, EGL_SYNC_STATUS_KHR, &v) && v == EGL_SIGNALED_KHR);
    CHECK_PIXEL(4, 4, 0, 0, 255, 255, 0);
    /* EGL_KHR_fence_sync names EGL_BAD_ATTRIBUTE for an unsupported type (EGL 1.5 says
     * EGL_BAD_PARAMETER). */
    CHECK(create_sync_khr(ct.display, 0x3333, NULL) == EGL_NO_SYNC_KHR);
    CHECK_EGL(EGL_BAD_ATTRIBUTE);
    CHECK(destroy_sync_khr(ct.display, s));
    CHECK(!destroy_sync_khr(ct.display, s));
    CHECK_EGL(EGL_BAD_PARAMETER);
}

int main(void)
{
    const char *egl_ext;
    ct_init(8, 8);
    egl_ext = eglQueryString(ct.display, EGL_EXTENSIONS);
    CHECK(ct_has_word(egl_ext, "EGL_KHR_fence_sync"));
    CHECK(ct_has_word(egl_ext, "EGL_KHR_wait_sync"));
    CHECK(ct_has_word((const char *)glGetString(GL_EXTENSIONS), "GL_OES_EGL_sync"));
    create_sync = (PFNEGLCREATESYNCPROC)eglGetProcAddress("eglCreateSync");
    destroy_sync = (PFNEGLDESTROYSYNCPROC)eglGetProcAddress("eglDestroySync");
    client_wait_sync = (PFNEGLCLIENTWAITSYNCPROC)eglGetProcAddress("eglClientWaitSync");
    get_sync_attrib = (PFNEGLGETSYNCATTRIBPROC)eglGetProcAddress("eglGetSyncAttrib");
    wait_sync = (PFNEGLWAITSYNCPROC)eglGetProcAddress("eglWaitSync");
    create_sync_khr = (PFNEGLCREATESYNCKHRPROC)eglGetProcAddress("eglCreateSyncKHR");
    destroy_sync_khr = (PFNEGLDESTROYSYNCKHRPROC)eglGetProcAddress("eglDestroySyncKHR");
    client_wait_sync_khr =
        (PFNEGLCLIENTWAITSYNCKHRPROC)eglGetProcAddress("eglClientWaitSyncKHR");
    get_sync_attrib_khr = (PFNEGLGETSYNCATTRIBKHRPROC)eglGetProcAddress("eglGetSyncAttribKHR");
    wait_sync_khr = (PFNEGLWAITSYNCKHRPROC)eglGetProcAddress("eglWaitSyncKHR");
    CHECK(create_sync && destroy_sync && client_wait_sync && get_sync_attrib && wait_sync &&
          create_sync_khr && destroy_sync_khr && client_wait_sync_khr && get_sync_attrib_khr &&
          wait_sync_khr);
    glDisable(GL_DITHER);
    core_fences();
    khr_fences();
    return ct_done();
}
