/* Tests of gsdc_support.h on its own, the C twin of the Rust support code's
 * tests (src/emit/rust/support_tests.rs): words, bit fields, the reading of
 * parameter telegrams and records, both PKW codecs at their edges, and the
 * diagnosis areas. tests/c_header.rs compiles it as C and as C++ and runs
 * it. */
#include "gsdc_support.h"

#include <stdio.h>
#include <stdlib.h>

static int failures = 0;

static void check(bool ok, const char *what, int line)
{
    if (!ok) {
        failures++;
        printf("support.c:%d: failed: %s\n", line, what);
    }
}

#define CHECK(condition) check((condition), #condition, __LINE__)

/* "10F0 0800": hex words into `out`, exactly `len` bytes. */
static void words(const char *hex, uint8_t *out, size_t len)
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

static bool same_bytes(const uint8_t *a, const uint8_t *b, size_t len)
{
    size_t i;
    for (i = 0U; i < len; i++) {
        if (a[i] != b[i]) {
            return false;
        }
    }
    return true;
}

static void words_are_big_endian(void)
{
    uint8_t bytes[4] = {0x13U, 0x88U, 0xFFU, 0xFFU};
    static const uint8_t written[4] = {0x13U, 0x88U, 0x07U, 0xD0U};
    CHECK(gsdc_u16be_get(bytes) == 5000U);
    CHECK(gsdc_word_get(bytes, 0U) == 0x1388U);
    gsdc_word_put(bytes, 1U, 0x07D0U);
    CHECK(same_bytes(bytes, written, 4U));
    CHECK(gsdc_word_get(bytes, 1U) == 2000U);
}

static void bit_fields_read_and_write_their_bits_only(void)
{
    /* MV810's control mode: bits 9-10. */
    CHECK(gsdc_field_get(0xFDFFU, 0x0600U, 9U) == 0x2U);
    CHECK(gsdc_field_with(0xFFFFU, 0x0600U, 9U, 0U) == 0xF9FFU);
    CHECK(gsdc_field_with(0U, 0x0600U, 9U, 0x7U) == 0x0600U); /* bits beyond are dropped */
    CHECK(gsdc_field_with(0x1234U, 0xFFFFU, 0U, 7U) == 7U);
    CHECK(gsdc_field_get(0x0008U, 0x0008U, 3U) == 1U);
}

/* An entry at index 0 holds an address from 0xF000 to 0xF0FF, the one at
 * index 1 a choice below 3. */
static bool two_entries(size_t index, uint16_t value)
{
    bool allowed;
    if (index < 1U) {
        allowed = (value >= 0xF000U) && (value <= 0xF0FFU);
    } else if (index < 2U) {
        allowed = value < 3U;
    } else {
        allowed = false;
    }
    return allowed;
}

static void values_are_read_and_checked_at_their_offset(void)
{
    static const uint8_t telegram[5] = {0x80U, 0xF0U, 0x12U, 0x00U, 0x02U};
    static const uint8_t bad_choice[5] = {0x80U, 0xF0U, 0x12U, 0x00U, 0x03U};
    static const uint8_t bad_address[5] = {0x80U, 0xA0U, 0x12U, 0x00U, 0x02U};
    uint16_t values[2] = {0U, 0U};
    gsdc_prm_result_t result;
    CHECK(gsdc_prm_read_values(telegram, 5U, 1U, 2U, two_entries, values).fault == GSDC_PRM_OK);
    CHECK(values[0] == 0xF012U);
    CHECK(values[1] == 2U);
    values[0] = 0U;
    result = gsdc_prm_read_values(bad_choice, 5U, 1U, 2U, two_entries, values);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 3U);
    CHECK(result.value == 3U);
    CHECK(values[0] == 0U); /* written only when all are allowed */
    result = gsdc_prm_read_values(bad_address, 5U, 1U, 2U, two_entries, values);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 1U);
    CHECK(result.value == 0xA012U);
}

static void reading_past_the_end_is_refused(void)
{
    static const uint8_t telegram[5] = {0x80U, 0xF0U, 0x12U, 0x00U, 0x02U};
    uint16_t values[2] = {0U, 0U};
    gsdc_prm_result_t result = gsdc_prm_read_values(telegram, 4U, 1U, 2U, two_entries, values);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(result.expected == 5U);
    CHECK(result.found == 4U);
    result = gsdc_prm_check_values(telegram, 5U, 6U, 1U, two_entries);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    result = gsdc_prm_check_values(telegram, 5U, (size_t)-1, 1U, two_entries);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(gsdc_prm_check_len(0U, 0U).fault == GSDC_PRM_OK);
    result = gsdc_prm_check_len(3U, 4U);
    CHECK((result.fault == GSDC_PRM_LENGTH) && (result.expected == 4U) && (result.found == 3U));
}

/* PKE, IND, PWE (MD810). */

static void pke_no_request_ignores_what_the_master_left(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    uint8_t zero[GSDC_PKW_BYTES] = {0};
    gsdc_pke_request_t request;
    gsdc_pke_response_t response;
    words("00F0 0800 0000 1388", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_request_decode(pkw, &request) == GSDC_PKW_OK);
    CHECK((request.command == GSDC_PKE_NO_REQUEST) && (request.address == 0U) &&
          (request.value == 0U));
    CHECK(gsdc_pke_request_encode(&request, pkw) == GSDC_PKW_OK);
    CHECK(same_bytes(pkw, zero, GSDC_PKW_BYTES));
    words("00F0 0800 0000 1388", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_response_decode(pkw, &response) == GSDC_PKW_OK);
    CHECK((response.code == GSDC_PKE_NO_REQUEST) && (response.value == 0U));
    response.address = 0xF008U;
    CHECK(gsdc_pke_response_encode(&response, pkw) == GSDC_PKW_OK);
    CHECK(same_bytes(pkw, zero, GSDC_PKW_BYTES));
}

static void pke_reserved_bits_are_not_read_and_written_0(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    uint8_t expected[GSDC_PKW_BYTES];
    gsdc_pke_request_t request;
    words("1FF0 08FF FFFF 0000", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_request_decode(pkw, &request) == GSDC_PKW_OK);
    CHECK((request.command == GSDC_PKE_READ) && (request.address == 0xF008U));
    request.value = 0x1234U; /* a read sends no value */
    CHECK(gsdc_pke_request_encode(&request, pkw) == GSDC_PKW_OK);
    words("10F0 0800 0000 0000", expected, GSDC_PKW_BYTES);
    CHECK(same_bytes(pkw, expected, GSDC_PKW_BYTES));
}

static void pke_codes_the_manual_does_not_define_are_refused(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    gsdc_pke_request_t request;
    gsdc_pke_response_t response;
    words("70F0 0800 0000 0005", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_response_decode(pkw, &response) == GSDC_PKW_BAD_ERROR_CODE);
    words("70F0 0800 0000 0000", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_response_decode(pkw, &response) == GSDC_PKW_BAD_ERROR_CODE);
    words("F0F0 0800 0000 0000", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_request_decode(pkw, &request) == GSDC_PKW_BAD_COMMAND);
    CHECK(request.command == 15U);
    CHECK(gsdc_pke_response_decode(pkw, &response) == GSDC_PKW_BAD_RESPONSE);
    CHECK(response.code == 15U);
}

/* Station, command, address, value (MV810). */

static void station_read_with_the_count_1(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    uint8_t expected[GSDC_PKW_BYTES];
    gsdc_station_request_t read;
    read.target = 1U;
    read.source = 0U;
    read.command = GSDC_STATION_READ;
    read.address = 0x2B02U;
    read.value = 0U;
    CHECK(gsdc_station_request_encode(&read, pkw) == GSDC_PKW_OK);
    words("0100 0003 2B02 0001", expected, GSDC_PKW_BYTES);
    CHECK(same_bytes(pkw, expected, GSDC_PKW_BYTES));
    CHECK(gsdc_station_request_decode(pkw, &read) == GSDC_PKW_OK);
    CHECK(read.value == 0U);
    words("0100 0003 2B02 0002", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_request_decode(pkw, &read) == GSDC_PKW_BAD_READ_COUNT);
    CHECK(read.value == 2U);
}

static void station_commands_the_manual_does_not_list_are_refused(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    gsdc_station_request_t request;
    gsdc_station_response_t response;
    words("0100 0000 0000 0000", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_request_decode(pkw, &request) == GSDC_PKW_BAD_COMMAND);
    words("0100 0083 2B02 0001", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_request_decode(pkw, &request) == GSDC_PKW_BAD_COMMAND);
    words("0001 0085 2B02 0001", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_response_decode(pkw, &response) == GSDC_PKW_BAD_COMMAND);
    CHECK(response.command == 0x85U);
    words("0001 0103 2B02 0001", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_response_decode(pkw, &response) == GSDC_PKW_BAD_COMMAND);
    words("0001 0080 2B02 0001", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_response_decode(pkw, &response) == GSDC_PKW_BAD_COMMAND);
}

static void station_errors_reply_0x80_plus_the_command(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    uint8_t expected[GSDC_PKW_BYTES];
    gsdc_station_response_t failed;
    failed.target = 0U;
    failed.source = 1U;
    failed.command = GSDC_STATION_WRITE;
    failed.failed = true;
    failed.address = 0x2B02U;
    failed.value = 2U;
    CHECK(gsdc_station_response_encode(&failed, pkw) == GSDC_PKW_OK);
    words("0001 0087 2B02 0002", expected, GSDC_PKW_BYTES);
    CHECK(same_bytes(pkw, expected, GSDC_PKW_BYTES));
}

/* Device-related diagnosis. */

static void an_area_is_its_bits_counted_from_the_byte_after_the_header(void)
{
    uint8_t block[3] = {3U, 0U, 0U};
    static const uint8_t low_byte[3] = {3U, 0U, 0x34U};
    static const uint8_t mode[3] = {3U, 0xF7U, 0xFFU};
    gsdc_diag_area_set(block, 3U, 8U, 15U, 0x34U);
    CHECK(same_bytes(block, low_byte, 3U));
    CHECK(gsdc_diag_area_get(block, 3U, 8U, 15U) == 0x34U);
    /* Two bits in the middle of the first byte, the rest untouched. */
    block[1] = 0xFFU;
    block[2] = 0xFFU;
    gsdc_diag_area_set(block, 3U, 2U, 3U, 0x1U);
    CHECK(same_bytes(block, mode, 3U));
    CHECK(gsdc_diag_area_get(block, 3U, 2U, 3U) == 0x1U);
    /* Bits of the value beyond the area are dropped. */
    gsdc_diag_area_set(block, 3U, 2U, 3U, 0x6U);
    CHECK(gsdc_diag_area_get(block, 3U, 2U, 3U) == 0x2U);
}

static void an_area_across_two_bytes_has_its_first_bit_lowest(void)
{
    uint8_t block[3] = {3U, 0U, 0U};
    static const uint8_t expected[3] = {3U, 0xB0U, 0x0AU};
    gsdc_diag_area_set(block, 3U, 4U, 11U, 0xABU);
    CHECK(same_bytes(block, expected, 3U));
    CHECK(gsdc_diag_area_get(block, 3U, 4U, 11U) == 0xABU);
}

static void a_block_too_short_loses_the_bits_past_its_end(void)
{
    uint8_t block[2] = {3U, 0U};
    gsdc_diag_area_set(block, 2U, 8U, 15U, 0x34U);
    CHECK((block[0] == 3U) && (block[1] == 0U));
    CHECK(gsdc_diag_area_get(block, 2U, 8U, 15U) == 0U);
    /* An area given backwards reads nothing, one wider than 16 bits its
     * first 16 bits. */
    block[1] = 0xFFU;
    CHECK(gsdc_diag_area_get(block, 2U, 15U, 8U) == 0U);
    CHECK(gsdc_diag_area_get(block, 2U, 4U, 0xFFFFU) == 0x000FU);
}

typedef struct {
    const char *name;
    void (*run)(void);
} test_t;

static const test_t tests[] = {
    {"words_are_big_endian", words_are_big_endian},
    {"bit_fields_read_and_write_their_bits_only", bit_fields_read_and_write_their_bits_only},
    {"values_are_read_and_checked_at_their_offset", values_are_read_and_checked_at_their_offset},
    {"reading_past_the_end_is_refused", reading_past_the_end_is_refused},
    {"pke_no_request_ignores_what_the_master_left", pke_no_request_ignores_what_the_master_left},
    {"pke_reserved_bits_are_not_read_and_written_0",
     pke_reserved_bits_are_not_read_and_written_0},
    {"pke_codes_the_manual_does_not_define_are_refused",
     pke_codes_the_manual_does_not_define_are_refused},
    {"station_read_with_the_count_1", station_read_with_the_count_1},
    {"station_commands_the_manual_does_not_list_are_refused",
     station_commands_the_manual_does_not_list_are_refused},
    {"station_errors_reply_0x80_plus_the_command", station_errors_reply_0x80_plus_the_command},
    {"an_area_is_its_bits_counted_from_the_byte_after_the_header",
     an_area_is_its_bits_counted_from_the_byte_after_the_header},
    {"an_area_across_two_bytes_has_its_first_bit_lowest",
     an_area_across_two_bytes_has_its_first_bit_lowest},
    {"a_block_too_short_loses_the_bits_past_its_end",
     a_block_too_short_loses_the_bits_past_its_end},
};

int main(void)
{
    size_t i;
    int passed = 0;
    int failed = 0;
    for (i = 0U; i < sizeof tests / sizeof tests[0]; i++) {
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
