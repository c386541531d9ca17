/* What a primitive costs under Mesa's llvmpipe, drawn alone: 1M tiny triangles that cover no
 * pixel centre (what Point Gaussian's 2 mm points are from 25 m), 1M triangles and lines that
 * cover a few pixels (what rain streaks are), 1M one-pixel points, 3M vertices of degenerate
 * triangles. Blending on, one constant colour, no interpolated values; the best of 3 draws.
 * Evidence for the Rain representation's frame time against Point Gaussian
 * (Testing/Benchmarks/README.md), not part of the build:
 *
 *   gcc -O2 Testing/Benchmarks/llvmpipe_primitive_costs.c -o /tmp/primitives -lglut -lGL
 *   scripts/with-xvfb.sh /tmp/primitives
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/freeglut.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum
{
  Count = 1000000
};

static double milliseconds(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

static GLuint program(void)
{
  const char* vs = "#version 330\nlayout(location = 0) in vec2 p;\nvoid main() { gl_Position = vec4(p, 0.5, 1.0); }\n";
  const char* fs = "#version 330\nout vec4 c;\nvoid main() { c = vec4(0.8, 0.8, 0.9, 0.05); }\n";
  GLuint v = glCreateShader(GL_VERTEX_SHADER), f = glCreateShader(GL_FRAGMENT_SHADER), p = glCreateProgram();
  glShaderSource(v, 1, &vs, 0);
  glCompileShader(v);
  glShaderSource(f, 1, &fs, 0);
  glCompileShader(f);
  glAttachShader(p, v);
  glAttachShader(p, f);
  glLinkProgram(p);
  return p;
}

/* Count primitives of `vertices` vertices at random places, `width` x `height` pixels each (a
 * width of 0: degenerate, every vertex at the first one). */
static void draw(const char* name, GLenum mode, int vertices, float width, float height, float* buffer)
{
  const float sx = 2.0f / 1280.0f, sy = 2.0f / 720.0f;
  for (int i = 0; i < Count; ++i)
  {
    const float x = 2.0f * rand() / (float)RAND_MAX - 1.0f, y = 2.0f * rand() / (float)RAND_MAX - 1.0f;
    float* b = buffer + 2 * vertices * i;
    for (int k = 0; k < vertices; ++k)
    {
      b[2 * k] = x + (k == 1 ? width * sx : 0.0f);
      b[2 * k + 1] = y - (k == vertices - 1 && k > 0 ? height * sy : 0.0f);
    }
  }
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)Count * vertices * 2 * sizeof(float), buffer, GL_STATIC_DRAW);
  double best = 1e30;
  for (int run = 0; run < 4; ++run)
  {
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    const double start = milliseconds();
    glDrawArrays(mode, 0, Count * vertices);
    glFinish();
    const double elapsed = milliseconds() - start;
    if (run > 0 && elapsed < best) /* the first draw uploads */
      best = elapsed;
  }
  printf("| %s | %.0f ms |\n", name, best);
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGBA);
  glutInitWindowSize(1280, 720);
  glutCreateWindow("llvmpipe primitive costs");
  glUseProgram(program());
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  float* buffer = malloc((size_t)Count * 6 * sizeof(float));
  printf("%s, 1280 x 720, 1M primitives a draw\n\n| primitive | draw |\n|---|---:|\n", glGetString(GL_RENDERER));
  draw("triangle 0.13 px (covers no pixel centre)", GL_TRIANGLES, 3, 0.13f, 0.13f, buffer);
  draw("triangle 2 x 5 px", GL_TRIANGLES, 3, 2.0f, 5.0f, buffer);
  draw("triangle 2 x 10 px", GL_TRIANGLES, 3, 2.0f, 10.0f, buffer);
  draw("line 4 px", GL_LINES, 2, 0.0f, 4.0f, buffer);
  draw("point 1 px", GL_POINTS, 1, 0.0f, 0.0f, buffer);
  draw("degenerate triangle", GL_TRIANGLES, 3, 0.0f, 0.0f, buffer);
  free(buffer);
  return 0;
}
