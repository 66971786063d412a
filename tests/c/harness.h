/* What the C test programs share: checks that count failures and name their
 * file and line, telegrams written as the manuals print them, and a main
 * loop that prints "ok <name>" per passing test and a summary, which
 * tests/c_header.rs reads. */
#ifndef GSDC_TEST_HARNESS_H
#define GSDC_TEST_HARNESS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static int failures = 0;

/* Counts a failed check, naming it, its file and its line. */
static inline void check(bool ok, const char *what, const char *file, int line)
{
    if (!ok) {
        failures++;
        printf("%s:%d: failed: %s\n", file, line, what);
    }
}

#define CHECK(condition) check((condition), #condition, __FILE__, __LINE__)

/* "10F0 0800 0000 1388", as the manuals print telegrams: hex words, into
 * `out`, which must be exactly as long. */
static inline void words(const char *hex, uint8_t *out, size_t len)
{
    size_t at = 0U;
    const char *p = hex;
    for (;;) {
        char *end = NULL;
        unsigned long word = strtoul(p, &end, 16);
        if (end == p) {
            break;
        }
        if (at + 2U <= len) {
            out[at] = (uint8_t)(word >> 8U);
            out[at + 1U] = (uint8_t)(word & 0xFFU);
        }
        at += 2U;
        p = end;
    }
    CHECK(at == len);
}

static inline bool same_bytes(const uint8_t *a, const uint8_t *b, size_t len)
{
    size_t i;
    for (i = 0U; i < len; i++) {
        if (a[i] != b[i]) {
            return false;
        }
    }
    return true;
}

typedef struct {
    const char *name;
    void (*run)(void);
} test_t;

/* Runs `count` tests in order: 0 when all pass, 1 otherwise. */
static inline int run_tests(const test_t *tests, size_t count)
{
    size_t i;
    int passed = 0;
    int failed = 0;
    for (i = 0U; i < count; i++) {
        int before = failures;
        tests[i].run();
        if (failures == before) {
            passed++;
            printf("ok %s\n", tests[i].name);
        } else {
            failed++;
            printf("FAILED %s\n", tests[i].name);
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

#endif
