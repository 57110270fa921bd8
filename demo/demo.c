/*
 * demo.c: a small OpenGL ES 1.1 + EGL 1.4 program, as an application would write it, that
 * renders an animated scene headless into a pbuffer and writes each frame as a PAM image.
 *
 * The scene: a lit, textured torus (two lights, one of them an orbiting point light,
 * specular highlights, a mipmapped checker texture), a tiled ground receding into linear
 * fog, two translucent glass panes (alpha blending, sorted back to front) and a fountain of
 * point sprites (OES_point_sprite with distance attenuation and additive blending). Nothing
 * in it is specific to this library: it builds against any GLES 1.1 / EGL 1.4.
 *
 *     cc -std=c99 -I include demo/demo.c -L target/release -lGLES_CM \
 *        -Wl,-rpath,$PWD/target/release -lm -o demo
 *     ./demo OUTDIR [FRAMES [WIDTH HEIGHT]]
 *
 * writes OUTDIR/frame-00.pam ... (RGBA, top row first) and prints each frame's render time.
 * `cargo run --release --bin showcase` compiles and runs it, and converts the frames to PNG.
 * Exit status: 0 on success, 1 when a GL or EGL call failed.
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */

#include <EGL/egl.h>
#include <GLES/gl.h>
#include <GLES/glext.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265f

/* ---- geometry ---------------------------------------------------------------------- */

/* Interleaved vertex: position, normal, texture coordinate. */
typedef struct {
    GLfloat pos[3], normal[3], tex[2];
} Vertex;

typedef struct {
    Vertex *vertices;
    GLushort *indices;
    int index_count;
} Mesh;

/* A torus around the Y axis: ring radius R, tube radius r; triangles counter-clockwise
 * seen from outside. */
static Mesh make_torus(float R, float r, int rings, int sides)
{
    Mesh m;
    int i, j, n = 0;
    m.vertices = malloc(sizeof(Vertex) * (size_t)((rings + 1) * (sides + 1)));
    m.indices = malloc(sizeof(GLushort) * (size_t)(rings * sides * 6));
    for (i = 0; i <= rings; ++i) {
        float u = 2 * PI * (float)i / (float)rings;
        for (j = 0; j <= sides; ++j) {
            float v = 2 * PI * (float)j / (float)sides;
            Vertex *p = &m.vertices[i * (sides + 1) + j];
            p->pos[0] = (R + r * cosf(v)) * cosf(u);
            p->pos[1] = r * sinf(v);
            p->pos[2] = (R + r * cosf(v)) * sinf(u);
            p->normal[0] = cosf(v) * cosf(u);
            p->normal[1] = sinf(v);
            p->normal[2] = cosf(v) * sinf(u);
            p->tex[0] = 8.0f * (float)i / (float)rings;
            p->tex[1] = 2.0f * (float)j / (float)sides;
        }
    }
    for (i = 0; i < rings; ++i) {
        for (j = 0; j < sides; ++j) {
            GLushort a = (GLushort)(i * (sides + 1) + j), b = (GLushort)(a + 1);
            GLushort c = (GLushort)(a + sides + 1), d = (GLushort)(c + 1);
            GLushort tri[6];
            tri[0] = a, tri[1] = b, tri[2] = c, tri[3] = c, tri[4] = b, tri[5] = d;
            memcpy(&m.indices[n], tri, sizeof tri);
            n += 6;
        }
    }
    m.index_count = n;
    return m;
}

/* A flat grid in the XZ plane at height y, `cells` x `cells` squares spanning
 * [-half, half]², normal up, texture repeating every 2 units. */
static Mesh make_ground(float half, float y, int cells)
{
    Mesh m;
    int i, j, n = 0;
    m.vertices = malloc(sizeof(Vertex) * (size_t)((cells + 1) * (cells + 1)));
    m.indices = malloc(sizeof(GLushort) * (size_t)(cells * cells * 6));
    for (i = 0; i <= cells; ++i) {
        for (j = 0; j <= cells; ++j) {
            Vertex *p = &m.vertices[i * (cells + 1) + j];
            p->pos[0] = -half + 2 * half * (float)i / (float)cells;
            p->pos[1] = y;
            p->pos[2] = -half + 2 * half * (float)j / (float)cells;
            p->normal[0] = 0, p->normal[1] = 1, p->normal[2] = 0;
            p->tex[0] = p->pos[0] * 0.5f;
            p->tex[1] = p->pos[2] * 0.5f;
        }
    }
    for (i = 0; i < cells; ++i) {
        for (j = 0; j < cells; ++j) {
            GLushort a = (GLushort)(i * (cells + 1) + j), b = (GLushort)(a + 1);
            GLushort c = (GLushort)(a + cells + 1), d = (GLushort)(c + 1);
            GLushort tri[6];
            tri[0] = a, tri[1] = b, tri[2] = c, tri[3] = c, tri[4] = b, tri[5] = d;
            memcpy(&m.indices[n], tri, sizeof tri);
            n += 6;
        }
    }
    m.index_count = n;
    return m;
}

static void draw_mesh(const Mesh *m)
{
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), m->vertices[0].pos);
    glNormalPointer(GL_FLOAT, sizeof(Vertex), m->vertices[0].normal);
    glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), m->vertices[0].tex);
    glDrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_SHORT, m->indices);
}

/* ---- textures ---------------------------------------------------------------------- */

static GLuint make_texture(int size, void (*texel)(int x, int y, int size, GLubyte out[4]),
                           GLenum wrap)
{
    GLubyte *pixels = malloc((size_t)size * (size_t)size * 4);
    GLuint name;
    int x, y;
    for (y = 0; y < size; ++y)
        for (x = 0; x < size; ++x)
            texel(x, y, size, pixels + 4 * (y * size + x));
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    free(pixels);
    return name;
}

static void set4(GLubyte out[4], int r, int g, int b, int a)
{
    out[0] = (GLubyte)r, out[1] = (GLubyte)g, out[2] = (GLubyte)b, out[3] = (GLubyte)a;
}

/* Warm checker for the torus. */
static void checker_texel(int x, int y, int size, GLubyte out[4])
{
    int cell = size / 4;
    if (((x / cell) + (y / cell)) & 1)
        set4(out, 240, 200, 90, 255);
    else
        set4(out, 200, 60, 40, 255);
}

/* Stone tiles with dark grout for the ground. */
static void tile_texel(int x, int y, int size, GLubyte out[4])
{
    int cell = size / 2, gx = x % cell, gy = y % cell;
    int grout = gx < 3 || gy < 3;
    int shade = ((x / cell) * 37 + (y / cell) * 91) % 40; /* each tile its own shade */
    int noise = ((x * 73 + y * 151) ^ (x * y)) % 16;
    if (grout)
        set4(out, 60, 60, 70, 255);
    else
        set4(out, 150 + shade + noise, 155 + shade + noise, 170 + shade, 255);
}

/* A soft round spark: white, alpha falling off from the center. */
static void spark_texel(int x, int y, int size, GLubyte out[4])
{
    float dx = ((float)x + 0.5f) / (float)size * 2 - 1, dy = ((float)y + 0.5f) / (float)size * 2 - 1;
    float d = sqrtf(dx * dx + dy * dy), a = d >= 1 ? 0 : (1 - d) * (1 - d);
    set4(out, 255, 255, 255, (int)(a * 255 + 0.5f));
}

/* ---- the frame --------------------------------------------------------------------- */

#define PARTICLES 300

/* A fixed pseudo-random number in [0, 1) for particle i, stream k. */
static float hash01(int i, int k)
{
    unsigned h = (unsigned)i * 2654435761u ^ (unsigned)k * 40503u;
    h ^= h >> 13, h *= 0x5bd1e995u, h ^= h >> 15;
    return (float)(h & 0xFFFFFF) / 16777216.0f;
}

typedef struct {
    Mesh torus, ground;
    GLuint checker, tiles, spark;
    int width, height;
} Scene;

static void draw_frame(const Scene *s, float t)
{
    static GLfloat sprite_pos[PARTICLES * 3], sprite_color[PARTICLES * 4];
    static const GLfloat fog_color[] = {0.55f, 0.65f, 0.80f, 1.0f};
    static const GLfloat sun_dir[] = {0.5f, 1.0f, 0.8f, 0.0f};
    static const GLfloat white[] = {1, 1, 1, 1}, dim[] = {0.25f, 0.25f, 0.3f, 1};
    static const GLfloat lamp_color[] = {1.0f, 0.55f, 0.25f, 1};
    static const GLfloat panes[2][4] = {{0.9f, 0.2f, 0.2f, 0.45f}, {0.2f, 0.5f, 1.0f, 0.45f}};
    static const GLfloat pane_x[2] = {-2.6f, 2.6f};
    float aspect = (float)s->width / (float)s->height, near_z = 0.5f;
    float top = near_z * tanf(25.0f * PI / 180.0f), cam = 30.0f + t * 40.0f;
    GLfloat lamp_pos[4];
    int i, order[2] = {0, 1};

    glViewport(0, 0, s->width, s->height);
    glClearColor(fog_color[0], fog_color[1], fog_color[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustumf(-top * aspect, top * aspect, -top, top, near_z, 40.0f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, -0.4f, -7.5f);
    glRotatef(18, 1, 0, 0);
    glRotatef(cam, 0, 1, 0);

    /* Lights are placed in world space (the camera is on the matrix). */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, dim);
    glLightfv(GL_LIGHT0, GL_POSITION, sun_dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    lamp_pos[0] = 2.2f * cosf(t * 2.0f);
    lamp_pos[1] = 0.8f;
    lamp_pos[2] = 2.2f * sinf(t * 2.0f);
    lamp_pos[3] = 1;
    glLightfv(GL_LIGHT1, GL_POSITION, lamp_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, lamp_color);
    glLightfv(GL_LIGHT1, GL_SPECULAR, lamp_color);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.25f);

    glEnable(GL_FOG);
    glFogf(GL_FOG_MODE, (GLfloat)GL_LINEAR);
    glFogf(GL_FOG_START, 6.0f);
    glFogf(GL_FOG_END, 18.0f);
    glFogfv(GL_FOG_COLOR, fog_color);

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);

    /* The ground: matte. */
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, dim);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8);
    glBindTexture(GL_TEXTURE_2D, s->tiles);
    draw_mesh(&s->ground);

    /* The torus: shiny, spinning, back faces culled. */
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);
    glBindTexture(GL_TEXTURE_2D, s->checker);
    glEnable(GL_CULL_FACE);
    glPushMatrix();
    glTranslatef(0, 0.6f, 0);
    glRotatef(t * 70.0f, 0, 1, 0);
    glRotatef(65.0f + 15.0f * sinf(t * 1.5f), 1, 0, 0);
    draw_mesh(&s->torus);
    glPopMatrix();
    glDisable(GL_CULL_FACE);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);

    /* Translucent panes, unlit and untextured, farthest first. The camera turns by `cam`
     * about Y, so a pane's eye-space depth grows with x * sin(cam). */
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    if (sinf(cam * PI / 180.0f) < 0)
        order[0] = 1, order[1] = 0;
    for (i = 0; i < 2; ++i) {
        int p = order[i];
        GLfloat quad[12];
        float x = pane_x[p];
        quad[0] = x, quad[1] = -1.2f, quad[2] = -1.3f;
        quad[3] = x, quad[4] = -1.2f, quad[5] = 1.3f;
        quad[6] = x, quad[7] = 1.6f, quad[8] = -1.3f;
        quad[9] = x, quad[10] = 1.6f, quad[11] = 1.3f;
        glColor4f(panes[p][0], panes[p][1], panes[p][2], panes[p][3]);
        glVertexPointer(3, GL_FLOAT, 0, quad);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }

    /* The fountain: point sprites, additive, sizes attenuated with distance. */
    for (i = 0; i < PARTICLES; ++i) {
        float life = 1.8f, age = fmodf(t + hash01(i, 0) * life, life), k = age / life;
        float vx = (hash01(i, 1) - 0.5f) * 2.4f, vz = (hash01(i, 2) - 0.5f) * 2.4f;
        float vy = 3.4f + hash01(i, 3) * 1.4f;
        sprite_pos[3 * i + 0] = vx * age;
        sprite_pos[3 * i + 1] = -1.2f + vy * age - 2.0f * age * age;
        sprite_pos[3 * i + 2] = vz * age;
        sprite_color[4 * i + 0] = 1.0f;
        sprite_color[4 * i + 1] = 0.75f - 0.55f * k;
        sprite_color[4 * i + 2] = 0.2f - 0.2f * k;
        sprite_color[4 * i + 3] = 0.7f * (1.0f - k);
    }
    {
        static const GLfloat attenuation[] = {0.0f, 0.0f, 1.0f / 49.0f};
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, s->spark);
        glEnable(GL_POINT_SPRITE_OES);
        glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, GL_TRUE);
        glPointSize(18.0f);
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
        glPointParameterf(GL_POINT_SIZE_MIN, 1.0f);
        glPointParameterf(GL_POINT_SIZE_MAX, 64.0f);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, sprite_pos);
        glColorPointer(4, GL_FLOAT, 0, sprite_color);
        glDrawArrays(GL_POINTS, 0, PARTICLES);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisable(GL_POINT_SPRITE_OES);
    }

    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_FOG);
    glColor4f(1, 1, 1, 1);
}

/* ---- output ------------------------------------------------------------------------ */

static int write_pam(const char *path, int width, int height, const GLubyte *rgba)
{
    FILE *f = fopen(path, "wb");
    int y;
    if (!f)
        return 0;
    fprintf(f, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n", width,
            height);
    /* GL's row 0 is the bottom row; images start at the top. */
    for (y = height - 1; y >= 0; --y)
        fwrite(rgba + (size_t)y * (size_t)width * 4, 4, (size_t)width, f);
    return fclose(f) == 0;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

int main(int argc, char **argv)
{
    static const EGLint config_attribs[] = {
        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
        EGL_DEPTH_SIZE, 16, EGL_NONE,
    };
    const char *out = argc > 1 ? argv[1] : ".";
    int frames = argc > 2 ? atoi(argv[2]) : 8;
    Scene s;
    EGLDisplay dpy;
    EGLConfig config;
    EGLint count = 0, major = 0, minor = 0;
    EGLint pbuffer_attribs[] = {EGL_WIDTH, 0, EGL_HEIGHT, 0, EGL_NONE};
    EGLSurface surface;
    EGLContext context;
    GLubyte *pixels;
    GLenum error;
    double total = 0;
    int f;

    s.width = argc > 4 ? atoi(argv[3]) : 512;
    s.height = argc > 4 ? atoi(argv[4]) : 384;
    if (frames < 1 || s.width < 1 || s.height < 1) {
        fprintf(stderr, "usage: %s OUTDIR [FRAMES [WIDTH HEIGHT]]\n", argv[0]);
        return 2;
    }
    pbuffer_attribs[1] = s.width;
    pbuffer_attribs[3] = s.height;

    /* EGL: display, config, pbuffer, context. */
    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
        fprintf(stderr, "demo: eglInitialize failed (0x%04X)\n", (unsigned)eglGetError());
        return 1;
    }
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count < 1) {
        fprintf(stderr, "demo: no RGBA8888 + depth config (0x%04X)\n", (unsigned)eglGetError());
        return 1;
    }
    surface = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
    context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (surface == EGL_NO_SURFACE || context == EGL_NO_CONTEXT ||
        !eglMakeCurrent(dpy, surface, surface, context)) {
        fprintf(stderr, "demo: no pbuffer context (0x%04X)\n", (unsigned)eglGetError());
        return 1;
    }
    printf("EGL %d.%d, %s\nGL_RENDERER %s, GL_VERSION %s\n", (int)major, (int)minor,
           eglQueryString(dpy, EGL_VENDOR), (const char *)glGetString(GL_RENDERER),
           (const char *)glGetString(GL_VERSION));

    s.torus = make_torus(1.3f, 0.45f, 48, 24);
    s.ground = make_ground(20.0f, -1.2f, 32);
    s.checker = make_texture(64, checker_texel, GL_REPEAT);
    s.tiles = make_texture(128, tile_texel, GL_REPEAT);
    s.spark = make_texture(32, spark_texel, GL_CLAMP_TO_EDGE);
    pixels = malloc((size_t)s.width * (size_t)s.height * 4);

    for (f = 0; f < frames; ++f) {
        char path[4096];
        double start = now_ms(), ms;
        draw_frame(&s, (float)f * 0.2f);
        glFinish(); /* rendering is deferred: the frame is done when glFinish returns */
        ms = now_ms() - start;
        total += ms;
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, s.width, s.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        snprintf(path, sizeof path, "%s/frame-%02d.pam", out, f);
        if (!write_pam(path, s.width, s.height, pixels)) {
            fprintf(stderr, "demo: cannot write %s\n", path);
            return 1;
        }
        printf("frame %d: %.1f ms\n", f, ms);
    }
    printf("%d frames of %dx%d, %.1f ms per frame on average\n", frames, s.width, s.height,
           total / frames);

    error = glGetError();
    if (error != GL_NO_ERROR)
        fprintf(stderr, "demo: GL error 0x%04X\n", (unsigned)error);
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, context);
    eglDestroySurface(dpy, surface);
    eglTerminate(dpy);
    eglReleaseThread();
    free(pixels);
    free(s.torus.vertices), free(s.torus.indices);
    free(s.ground.vertices), free(s.ground.indices);
    return error == GL_NO_ERROR ? 0 : 1;
}
