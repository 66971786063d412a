/* Tests of gsdc_support.h on its own, the C twin of the Rust support code's
 * tests (src/emit/rust/support_tests.rs and support_gateway_tests.rs): words,
 * bit fields, the reading of parameter telegrams and records, the PKW codecs
 * at their edges, the diagnosis areas, and the gateways' parameters, totals
 * and diagnosis blocks. tests/c_header.rs compiles it as C and as C++ and
 * runs it. */
#include "gsdc_support.h"

#include "harness.h"

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

static size_t two_bytes(size_t index)
{
    (void)index;
    return 2U;
}

/* ABB FENA's record 1: two Integer8 settings (0 to 2, 0 to 1), then an
 * Unsigned16. */
static bool fena_allows(size_t index, uint16_t value)
{
    static const uint16_t max[3] = {2U, 1U, 0xFFFFU};
    return (index < 3U) && (value <= max[index]);
}

static size_t fena_bytes(size_t index)
{
    static const size_t bytes[3] = {1U, 1U, 2U};
    return (index < 3U) ? bytes[index] : 2U;
}

static void byte_and_word_entries_are_read_each_at_its_offset(void)
{
    static const uint8_t record[4] = {2U, 1U, 0x04U, 0x7EU};
    static const uint8_t refused[4] = {0U, 2U, 0U, 0U};
    uint16_t values[3] = {0U, 0U, 0U};
    gsdc_prm_result_t result;
    CHECK(gsdc_prm_read_values(record, 4U, 0U, 3U, fena_allows, fena_bytes, values).fault ==
          GSDC_PRM_OK);
    CHECK((values[0] == 2U) && (values[1] == 1U) && (values[2] == 0x047EU));
    result = gsdc_prm_read_values(record, 3U, 0U, 3U, fena_allows, fena_bytes, values);
    CHECK((result.fault == GSDC_PRM_LENGTH) && (result.expected == 4U) && (result.found == 3U));
    result = gsdc_prm_read_values(refused, 4U, 0U, 3U, fena_allows, fena_bytes, values);
    CHECK((result.fault == GSDC_PRM_NOT_ALLOWED) && (result.offset == 1U) && (result.value == 2U));
}

/* FENA's standard telegram 2: record 1 holds the two Integer8 settings,
 * then the fail-safe values of STW1, NSOLL_B (32 bits) and STW2. */
static void a_record_ends_with_its_fail_safe_values(void)
{
    static const size_t entries[2] = {0U, 1U};
    static const uint16_t defaults[2] = {0U, 0U};
    static const bool changeable[2] = {true, true};
    static const uint8_t widths[3] = {2U, 4U, 2U};
    static const uint8_t bytes[10] = {2U, 1U, 0x04U, 0x7EU, 0x00U, 0x01U, 0x86U, 0xA0U, 0xABU, 0xCDU};
    gsdc_pn_record_t record;
    uint16_t settings[2] = {9U, 9U};
    uint32_t values[3] = {9U, 9U, 9U};
    gsdc_prm_result_t result;
    record.index = 1U;
    record.len = 10U;
    record.reading = GSDC_RECORD_READING_WHOLE;
    record.allows = fena_allows;
    record.entry_bytes = fena_bytes;
    record.entries = entries;
    record.entries_count = 2U;
    record.defaults = defaults;
    record.defaults_count = 2U;
    record.changeable = changeable;
    record.changeable_count = 2U;
    record.fail_safe = widths;
    record.fail_safe_count = 3U;
    CHECK(gsdc_pn_record_decode(&record, bytes, 10U, settings).fault == GSDC_PRM_OK);
    CHECK((settings[0] == 2U) && (settings[1] == 1U));
    CHECK(gsdc_pn_record_fail_safe(&record, bytes, 10U, values).fault == GSDC_PRM_OK);
    CHECK((values[0] == 0x047EUL) && (values[1] == 100000UL) && (values[2] == 0xABCDUL));
    values[1] = 9U;
    result = gsdc_pn_record_fail_safe(&record, bytes, 9U, values);
    CHECK((result.fault == GSDC_PRM_LENGTH) && (result.expected == 10U) && (result.found == 9U));
    CHECK(values[1] == 9U); /* written only when the record is whole */
    /* A table whose entries and values would not fit its length is refused,
     * not read past. */
    record.len = 4U;
    result = gsdc_pn_record_fail_safe(&record, bytes, 4U, values);
    CHECK((result.fault == GSDC_PRM_LENGTH) && (result.expected == 10U) && (result.found == 4U));
    CHECK(values[1] == 9U);
}

/* A value of a record of the access point or a port: whole bytes, or bits
 * of one byte when `bytes` is 0; any value, changeable. */
static gsdc_pn_record_value_t record_value(size_t offset, size_t bytes, uint8_t first_bit,
                                           uint8_t last_bit)
{
    gsdc_pn_record_value_t v;
    v.name = "value";
    v.offset = offset;
    v.bytes = bytes;
    v.first_bit = first_bit;
    v.last_bit = last_bit;
    v.default_value = 0U;
    v.min = 0U;
    v.max = 0xFFFFFFFFUL;
    v.values = NULL;
    v.values_count = 0U;
    v.changeable = true;
    return v;
}

/* SEW MOVI-C's records of a port and of its access point, as the Rust
 * support's test has them: record 9001's two Unsigned32 thresholds, high
 * byte first; record 8200's alarm bit (0 or 1) in bit 0, beside a bit area
 * of bits 4 to 6 that holds 1 to 5 and a byte nobody may change from its
 * default 1. */
static void an_access_point_record_reads_whole_values_and_bits(void)
{
    static const uint8_t thresholds_bytes[8] = {0U, 0U, 0U, 10U, 0x00U, 0x01U, 0x86U, 0xA0U};
    static const uint32_t on_off[2] = {0U, 1U};
    static const uint8_t set[2] = {0x51U, 1U};     /* bit 0, bits 4 to 6 = 5 */
    static const uint8_t too_high[2] = {0x60U, 1U}; /* bits 4 to 6 = 6 */
    static const uint8_t changed[2] = {0x10U, 2U};
    gsdc_pn_record_value_t thresholds_values[2];
    gsdc_pn_record_value_t alarm_values[3];
    gsdc_pn_submodule_record_t thresholds;
    gsdc_pn_submodule_record_t alarms;
    uint32_t out[3] = {9U, 9U, 9U};
    gsdc_prm_result_t result;
    thresholds_values[0] = record_value(0U, 4U, 0U, 7U);
    thresholds_values[1] = record_value(4U, 4U, 0U, 7U);
    thresholds.index = 9001U;
    thresholds.len = 8U;
    thresholds.values = thresholds_values;
    thresholds.values_count = 2U;
    CHECK(gsdc_pn_submodule_record_decode(&thresholds, thresholds_bytes, 8U, out).fault == GSDC_PRM_OK);
    CHECK((out[0] == 10U) && (out[1] == 100000UL));
    result = gsdc_pn_submodule_record_decode(&thresholds, thresholds_bytes, 7U, out);
    CHECK((result.fault == GSDC_PRM_LENGTH) && (result.expected == 8U) && (result.found == 7U));
    alarm_values[0] = record_value(0U, 0U, 0U, 0U);
    alarm_values[0].max = 1U;
    alarm_values[0].values = on_off;
    alarm_values[0].values_count = 2U;
    alarm_values[1] = record_value(0U, 0U, 4U, 6U);
    alarm_values[1].min = 1U;
    alarm_values[1].max = 5U;
    alarm_values[1].default_value = 2U;
    alarm_values[2] = record_value(1U, 1U, 0U, 7U);
    alarm_values[2].default_value = 1U;
    alarm_values[2].changeable = false;
    alarms.index = 8200U;
    alarms.len = 2U;
    alarms.values = alarm_values;
    alarms.values_count = 3U;
    CHECK(gsdc_pn_submodule_record_decode(&alarms, set, 2U, out).fault == GSDC_PRM_OK);
    CHECK((out[0] == 1U) && (out[1] == 5U) && (out[2] == 1U));
    result = gsdc_pn_submodule_record_decode(&alarms, too_high, 2U, out);
    CHECK((result.fault == GSDC_PRM_NOT_ALLOWED) && (result.offset == 0U) && (result.value == 6U));
    result = gsdc_pn_submodule_record_decode(&alarms, changed, 2U, out);
    CHECK((result.fault == GSDC_PRM_NOT_ALLOWED) && (result.offset == 1U) && (result.value == 2U));
    CHECK((out[0] == 1U) && (out[1] == 5U) && (out[2] == 1U)); /* written only when accepted */
}

static void values_are_read_and_checked_at_their_offset(void)
{
    static const uint8_t telegram[5] = {0x80U, 0xF0U, 0x12U, 0x00U, 0x02U};
    static const uint8_t bad_choice[5] = {0x80U, 0xF0U, 0x12U, 0x00U, 0x03U};
    static const uint8_t bad_address[5] = {0x80U, 0xA0U, 0x12U, 0x00U, 0x02U};
    uint16_t values[2] = {0U, 0U};
    gsdc_prm_result_t result;
    CHECK(gsdc_prm_read_values(telegram, 5U, 1U, 2U, two_entries, two_bytes, values).fault == GSDC_PRM_OK);
    CHECK(values[0] == 0xF012U);
    CHECK(values[1] == 2U);
    values[0] = 0U;
    result = gsdc_prm_read_values(bad_choice, 5U, 1U, 2U, two_entries, two_bytes, values);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 3U);
    CHECK(result.value == 3U);
    CHECK(values[0] == 0U); /* written only when all are allowed */
    result = gsdc_prm_read_values(bad_address, 5U, 1U, 2U, two_entries, two_bytes, values);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 1U);
    CHECK(result.value == 0xA012U);
}

static void reading_past_the_end_is_refused(void)
{
    static const uint8_t telegram[5] = {0x80U, 0xF0U, 0x12U, 0x00U, 0x02U};
    uint16_t values[2] = {0U, 0U};
    gsdc_prm_result_t result = gsdc_prm_read_values(telegram, 4U, 1U, 2U, two_entries, two_bytes, values);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(result.expected == 5U);
    CHECK(result.found == 4U);
    result = gsdc_prm_check_values(telegram, 5U, 6U, 1U, two_entries, two_bytes);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    result = gsdc_prm_check_values(telegram, 5U, (size_t)-1, 1U, two_entries, two_bytes);
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

/* PROFIdrive: PKE (id, SPM, PNU), IND (subindex), PWE1, PWE2. */

static void profidrive_words_in_pwe2_double_words_across_both(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    uint8_t expected[GSDC_PKW_BYTES];
    gsdc_profidrive_request_t request;
    gsdc_profidrive_response_t response;
    request.id = GSDC_PROFIDRIVE_WRITE_DOUBLE_WORD;
    request.pnu = 1005U;
    request.subindex = 0U;
    request.value = 0x000186A0UL;
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_OK);
    words("33ED 0000 0001 86A0", expected, GSDC_PKW_BYTES);
    CHECK(same_bytes(pkw, expected, GSDC_PKW_BYTES));
    /* PWE1 of a word is written 0 and not read. */
    words("13ED 0000 FFFF 1388", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_profidrive_response_decode(pkw, &response) == GSDC_PKW_OK);
    CHECK(response.value == 5000U);
    CHECK(gsdc_profidrive_response_encode(&response, pkw) == GSDC_PKW_OK);
    words("13ED 0000 0000 1388", expected, GSDC_PKW_BYTES);
    CHECK(same_bytes(pkw, expected, GSDC_PKW_BYTES));
    words("23ED 0000 0001 86A0", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_profidrive_response_decode(pkw, &response) == GSDC_PKW_OK);
    CHECK(response.id == GSDC_PROFIDRIVE_VALUE_DOUBLE_WORD);
    CHECK(response.value == 100000UL);
}

/* The subindex is IND's high byte; its low byte and SPM are written 0 and
 * not read. */
static void profidrive_the_subindex_is_the_high_byte_of_ind(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    uint8_t expected[GSDC_PKW_BYTES];
    gsdc_profidrive_request_t request;
    words("7BED 02FF 0000 0007", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_profidrive_request_decode(pkw, &request) == GSDC_PKW_OK);
    CHECK(request.id == GSDC_PROFIDRIVE_WRITE_ARRAY_WORD);
    CHECK(request.pnu == 1005U);
    CHECK(request.subindex == 2U);
    CHECK(request.value == 7U);
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_OK);
    words("73ED 0200 0000 0007", expected, GSDC_PKW_BYTES);
    CHECK(same_bytes(pkw, expected, GSDC_PKW_BYTES));
}

static void profidrive_ids_beyond_the_profile_are_refused(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    gsdc_profidrive_request_t request;
    gsdc_profidrive_response_t response;
    unsigned int id;
    for (id = 10U; id <= 15U; id++) {
        pkw[0] = (uint8_t)((id << 4U) | 0x03U);
        pkw[1] = 0xEDU;
        pkw[2] = 1U;
        pkw[3] = 0U;
        CHECK(gsdc_profidrive_request_decode(pkw, &request) == GSDC_PKW_BAD_COMMAND);
        CHECK(request.id == id);
        CHECK(request.pnu == 1005U);
        CHECK(request.subindex == 1U);
        CHECK(gsdc_profidrive_response_decode(pkw, &response) ==
              (id <= 12U ? GSDC_PKW_CHANGE_REPORT : GSDC_PKW_BAD_RESPONSE));
    }
    pkw[0] = 0x93U;
    CHECK(gsdc_profidrive_response_decode(pkw, &response) == GSDC_PKW_CHANGE_REPORT);
    CHECK(response.id == 9U);
}

/* A PNU beyond 11 bits or a word beyond 16 bits is refused, `pkw` left as
 * it was. */
static void profidrive_encoders_refuse_what_the_channel_cannot_carry(void)
{
    uint8_t pkw[GSDC_PKW_BYTES] = {1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U};
    static const uint8_t untouched[GSDC_PKW_BYTES] = {1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U};
    gsdc_profidrive_request_t request;
    gsdc_profidrive_response_t response;
    request.id = GSDC_PROFIDRIVE_READ;
    request.pnu = GSDC_PROFIDRIVE_PNU_MAX + 1U;
    request.subindex = 0U;
    request.value = 0U;
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_BAD_PNU);
    request.id = GSDC_PROFIDRIVE_WRITE_WORD;
    request.pnu = GSDC_PROFIDRIVE_PNU_MAX;
    request.value = 0x10000UL;
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_BAD_VALUE);
    response.id = GSDC_PROFIDRIVE_CANNOT_EXECUTE;
    response.pnu = 0U;
    response.subindex = 0U;
    response.value = 0x10000UL;
    CHECK(gsdc_profidrive_response_encode(&response, pkw) == GSDC_PKW_BAD_VALUE);
    response.id = 9U;
    response.value = 0U;
    CHECK(gsdc_profidrive_response_encode(&response, pkw) == GSDC_PKW_BAD_RESPONSE);
    CHECK(same_bytes(pkw, untouched, GSDC_PKW_BYTES));
    /* The largest PNU and a double word of 32 bits pass. */
    request.id = GSDC_PROFIDRIVE_WRITE_DOUBLE_WORD;
    request.value = 0xFFFFFFFFUL;
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_OK);
    CHECK(gsdc_u16be_get(&pkw[0]) == 0x37FFU);
}

static void profidrive_no_request_ignores_what_the_master_left(void)
{
    uint8_t pkw[GSDC_PKW_BYTES];
    gsdc_profidrive_request_t request;
    words("03ED 0200 1234 5678", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_profidrive_request_decode(pkw, &request) == GSDC_PKW_OK);
    CHECK(request.id == GSDC_PROFIDRIVE_NO_REQUEST);
    CHECK(request.pnu == 0U);
    CHECK(request.subindex == 0U);
    CHECK(request.value == 0U);
    request.pnu = 1005U;
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_OK);
    CHECK(gsdc_u16be_get(&pkw[0]) == 0U);
    CHECK(gsdc_u16be_get(&pkw[2]) == 0U);
    CHECK(gsdc_u16be_get(&pkw[6]) == 0U);
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

/* ------------------------------------------------------------------------
 * Gateways: what the shipped gateway (whole bytes, tested in manuals.c)
 * does not reach, as src/emit/rust/support_gateway_tests.rs tests it. */

/* Two parameters in one byte: words in (bits 0-3) and out (bits 4-7). */
static const gsdc_prm_field_t in_bits = {1U, GSDC_PRM_BITS, 0U, 3U, 0U, 8U, 0U};
static const gsdc_prm_field_t out_bits = {1U, GSDC_PRM_BITS, 4U, 7U, 0U, 8U, 2U};

static void bit_areas_share_a_byte(void)
{
    uint8_t user_prm[2] = {0xAAU, 0x00U};
    static const uint8_t both[2] = {0xAAU, 0x85U};
    static const uint8_t again[2] = {0xAAU, 0x83U};
    CHECK(gsdc_prm_field_check_value(&in_bits, 2U, 5U).fault == GSDC_PRM_OK);
    gsdc_prm_field_put(&in_bits, user_prm, 5U);
    gsdc_prm_field_put(&out_bits, user_prm, 8U);
    CHECK(same_bytes(user_prm, both, 2U));
    gsdc_prm_field_put(&in_bits, user_prm, 3U);
    CHECK(same_bytes(user_prm, again, 2U));
    CHECK(gsdc_prm_field_get(&in_bits, user_prm) == 3U);
    CHECK(gsdc_prm_field_get(&out_bits, user_prm) == 8U);
    CHECK(gsdc_prm_field_check(&out_bits, user_prm, 2U).fault == GSDC_PRM_OK);
}

static void bits_beyond_the_range_are_refused(void)
{
    /* 0xF in bits 0-3: the type holds it, the range does not. */
    static const uint8_t fifteen[2] = {0x00U, 0x0FU};
    gsdc_prm_result_t result = gsdc_prm_field_check(&in_bits, fifteen, 2U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 1U && result.value == 15U);
    result = gsdc_prm_field_check_value(&out_bits, 2U, 9U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 1U && result.value == 9U);
}

static void unsigned16_is_big_endian_and_within_a_byte_s_values(void)
{
    static const gsdc_prm_field_t words = {0U, GSDC_PRM_UNSIGNED16, 0U, 0U, 0U, 200U, 0U};
    static const uint8_t written[3] = {0x00U, 0xC8U, 0xFFU};
    static const uint8_t too_big[2] = {0x01U, 0x00U};
    uint8_t user_prm[3] = {0xFFU, 0xFFU, 0xFFU};
    gsdc_prm_result_t result;
    CHECK(gsdc_prm_field_check_value(&words, 3U, 200U).fault == GSDC_PRM_OK);
    gsdc_prm_field_put(&words, user_prm, 200U);
    CHECK(same_bytes(user_prm, written, 3U));
    CHECK(gsdc_prm_field_check(&words, user_prm, 3U).fault == GSDC_PRM_OK);
    CHECK(gsdc_prm_field_get(&words, user_prm) == 200U);
    result = gsdc_prm_field_check(&words, too_big, 2U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED);
    CHECK(result.offset == 0U && result.value == 256U);
}

static void a_field_past_the_end_is_a_length_error(void)
{
    static const uint8_t short_prm[1] = {0U};
    gsdc_prm_result_t result = gsdc_prm_field_check(&in_bits, short_prm, 1U);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(result.expected == 2U && result.found == 1U);
    result = gsdc_prm_field_check_value(&out_bits, 1U, 1U);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(result.expected == 2U && result.found == 1U);
}

static void config_bytes_of_no_module_are_refused(void)
{
    static const uint8_t modules[3] = {0x50U, 0x5FU, 0x60U};
    static const uint8_t plugged[4] = {0x5FU, 0x50U, 0x60U, 0x5FU};
    /* 0x70: input and output of one word, a byte no module of a gateway has. */
    static const uint8_t both_ways[1] = {0x70U};
    static const uint8_t unlisted[1] = {0x51U};
    gsdc_totals_t totals = gsdc_config_totals(plugged, 4U, modules, 3U, 4U);
    CHECK(totals.fault == GSDC_TOTALS_OK);
    CHECK(totals.input_words == 33U && totals.output_words == 1U);
    totals = gsdc_config_totals(both_ways, 1U, both_ways, 1U, 4U);
    CHECK(totals.fault == GSDC_TOTALS_UNKNOWN_MODULE && totals.at == 0U && totals.byte == 0x70U);
    totals = gsdc_config_totals(unlisted, 1U, modules, 3U, 4U);
    CHECK(totals.fault == GSDC_TOTALS_UNKNOWN_MODULE && totals.at == 0U && totals.byte == 0x51U);
    CHECK(totals.input_words == 0U && totals.output_words == 0U);
}

/* A gateway of nodes 5 to 7: at most 4 words each way per node, 10 bytes of
 * input and 6 of output; words in byte 1 + node, out in byte 4 + node. */
static gsdc_node_params_t small_gateway(void)
{
    static const gsdc_prm_field_t count = {0U, GSDC_PRM_UNSIGNED8, 0U, 0U, 1U, 3U, 1U};
    static const gsdc_prm_field_t input[3] = {{1U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 4U, 0U},
                                              {2U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 4U, 0U},
                                              {3U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 4U, 0U}};
    static const gsdc_prm_field_t output[3] = {{4U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 4U, 0U},
                                               {5U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 4U, 0U},
                                               {6U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 4U, 0U}};
    gsdc_node_params_t params;
    params.first_node = 5U;
    params.nodes = 3U;
    params.node_count = &count;
    params.input_words = input;
    params.output_words = output;
    params.max_input_len = 10U;
    params.max_output_len = 6U;
    return params;
}

typedef struct {
    uint8_t count;
    uint8_t input[3];
    uint8_t output[3];
    gsdc_totals_fault_t fault;
    uint8_t node;
    gsdc_direction_t direction;
    size_t len;
} small_refused_t;

static void totals_count_the_nodes_in_use_within_the_limits(void)
{
    static const uint8_t input[3] = {2U, 0U, 3U};
    static const uint8_t output[3] = {1U, 1U, 1U};
    static const small_refused_t refused[6] = {
        {0U, {0U, 0U, 0U}, {0U, 0U, 0U}, GSDC_TOTALS_NODE_COUNT, 0U, GSDC_DIRECTION_NONE, 0U},
        {4U, {0U, 0U, 0U}, {0U, 0U, 0U}, GSDC_TOTALS_NODE_COUNT, 0U, GSDC_DIRECTION_NONE, 0U},
        {3U, {0U, 5U, 0U}, {0U, 0U, 0U}, GSDC_TOTALS_WORDS, 6U, GSDC_DIRECTION_IN, 0U},
        {1U, {0U, 0U, 0U}, {0U, 0U, 1U}, GSDC_TOTALS_UNUSED_NODE, 7U, GSDC_DIRECTION_NONE, 0U},
        {2U, {4U, 2U, 0U}, {0U, 0U, 0U}, GSDC_TOTALS_TOO_LONG, 0U, GSDC_DIRECTION_IN, 12U},
        {3U, {0U, 0U, 0U}, {2U, 1U, 1U}, GSDC_TOTALS_TOO_LONG, 0U, GSDC_DIRECTION_OUT, 8U},
    };
    gsdc_node_params_t params = small_gateway();
    gsdc_totals_t totals = gsdc_node_totals(&params, 3U, input, output);
    size_t i;
    CHECK(totals.fault == GSDC_TOTALS_OK);
    CHECK(gsdc_totals_input_len(&totals) == 10U && gsdc_totals_output_len(&totals) == 6U);
    for (i = 0U; i < 6U; i++) {
        const small_refused_t *r = &refused[i];
        totals = gsdc_node_totals(&params, r->count, r->input, r->output);
        CHECK(totals.fault == r->fault);
        CHECK(totals.node == r->node && totals.direction == r->direction);
        CHECK(totals.len == r->len);
        CHECK(totals.input_words == 0U && totals.output_words == 0U);
    }
    totals = gsdc_node_totals(&params, 4U, input, output);
    CHECK(totals.count == 4U);
    totals = gsdc_node_totals(&params, 3U, refused[2].input, output);
    CHECK(totals.words == 5U);
}

/* A count its parameter allows is still refused past the nodes there are. */
static void a_count_past_the_nodes_is_refused(void)
{
    static const gsdc_prm_field_t wide = {0U, GSDC_PRM_UNSIGNED8, 0U, 0U, 1U, 5U, 1U};
    static const uint8_t none[3] = {0U, 0U, 0U};
    gsdc_node_params_t params = small_gateway();
    gsdc_totals_t totals;
    params.node_count = &wide;
    CHECK(gsdc_node_totals(&params, 3U, none, none).fault == GSDC_TOTALS_OK);
    totals = gsdc_node_totals(&params, 4U, none, none);
    CHECK(totals.fault == GSDC_TOTALS_NODE_COUNT && totals.count == 4U);
}

static void data_offsets_follow_the_nodes_in_use(void)
{
    static const uint8_t words[3] = {2U, 0U, 3U};
    gsdc_node_params_t params = small_gateway();
    size_t offset = 99U;
    CHECK(gsdc_node_offset(&params, 3U, words, 5U, &offset) && offset == 0U);
    CHECK(gsdc_node_offset(&params, 3U, words, 7U, &offset) && offset == 4U);
    offset = 99U;
    CHECK(!gsdc_node_offset(&params, 2U, words, 7U, &offset));
    CHECK(!gsdc_node_offset(&params, 3U, words, 4U, &offset));
    CHECK(!gsdc_node_offset(&params, 3U, words, 8U, &offset));
    CHECK(offset == 99U);
}

/* The count, then every node's input words, then every node's output
 * words: the first fault in that order is the one reported, and a refused
 * write writes nothing. */
static void nodes_read_and_write_in_order(void)
{
    static const uint8_t input[3] = {1U, 2U, 3U};
    static const uint8_t output[3] = {4U, 0U, 4U};
    static const uint8_t bad_output[3] = {4U, 5U, 4U};
    static const uint8_t written[8] = {3U, 1U, 2U, 3U, 4U, 0U, 4U, 0xEEU};
    gsdc_node_params_t params = small_gateway();
    uint8_t user_prm[8] = {0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU};
    uint8_t count = 0U;
    uint8_t read_in[3] = {0U, 0U, 0U};
    uint8_t read_out[3] = {0U, 0U, 0U};
    gsdc_prm_result_t result = gsdc_nodes_put(&params, 3U, input, bad_output, user_prm, 8U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 5U && result.value == 5U);
    CHECK(user_prm[0] == 0xEEU && user_prm[1] == 0xEEU);
    CHECK(gsdc_nodes_put(&params, 3U, input, output, user_prm, 8U).fault == GSDC_PRM_OK);
    CHECK(same_bytes(user_prm, written, 8U));
    CHECK(gsdc_nodes_check(&params, user_prm, 8U).fault == GSDC_PRM_OK);
    gsdc_nodes_get(&params, user_prm, &count, read_in, read_out);
    CHECK(count == 3U && same_bytes(read_in, input, 3U) && same_bytes(read_out, output, 3U));
    user_prm[2] = 9U; /* an input word */
    user_prm[4] = 9U; /* an output word, before it in the telegram */
    result = gsdc_nodes_check(&params, user_prm, 8U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 2U);
    result = gsdc_nodes_check(&params, user_prm, 6U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 2U);
    user_prm[2] = 2U;
    result = gsdc_nodes_check(&params, user_prm, 6U);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 4U);
    user_prm[4] = 4U;
    result = gsdc_nodes_check(&params, user_prm, 6U);
    CHECK(result.fault == GSDC_PRM_LENGTH && result.expected == 7U && result.found == 6U);
}

/* Type, node and code after the header; nodes 5 to 7; type 1 has one-byte
 * codes, of which 3 is the only one, type 9 a 16-bit code. */
static bool code_three(uint16_t value)
{
    return value == 3U;
}

static gsdc_diag_layout_t small_diag(void)
{
    static const gsdc_diag_type_t types[2] = {{1U, 4U, code_three}, {9U, 5U, NULL}};
    gsdc_diag_layout_t layout;
    layout.type_at = 1U;
    layout.node_at = 2U;
    layout.code_at = 3U;
    layout.first_node = 5U;
    layout.last_node = 7U;
    layout.types = types;
    layout.type_count = 2U;
    return layout;
}

static void diagnosis_blocks_are_read_as_long_as_their_header_says(void)
{
    static const uint8_t word[6] = {5U, 9U, 6U, 0xBEU, 0xEFU, 0x11U};
    static const uint8_t byte_code[4] = {4U, 1U, 7U, 3U};
    gsdc_diag_layout_t layout = small_diag();
    uint8_t block[6] = {0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU};
    uint8_t kind = 0U;
    uint8_t node = 0U;
    uint16_t code = 0U;
    size_t len = 0U;
    gsdc_diag_result_t result;
    CHECK(gsdc_diag_encode(&layout, 9U, 6U, 0xBEEFU, block, &len).fault == GSDC_DIAG_OK);
    CHECK(len == 5U && same_bytes(block, word, 5U) && block[5] == 0xEEU);
    CHECK(gsdc_diag_decode(&layout, word, 6U, &kind, &node, &code).fault == GSDC_DIAG_OK);
    CHECK(kind == 9U && node == 6U && code == 0xBEEFU);
    CHECK(gsdc_diag_encode(&layout, 1U, 7U, 3U, block, &len).fault == GSDC_DIAG_OK);
    CHECK(len == 4U && same_bytes(block, byte_code, 4U));
    CHECK(gsdc_diag_decode(&layout, byte_code, 4U, &kind, &node, &code).fault == GSDC_DIAG_OK);
    CHECK(kind == 1U && node == 7U && code == 3U);
    /* A type-1 block with a fifth byte: its header says 5, type 1 has 4. */
    block[0] = 5U;
    result = gsdc_diag_decode(&layout, block, 5U, &kind, &node, &code);
    CHECK(result.fault == GSDC_DIAG_LENGTH && result.expected == 4U && result.found == 5U);
    block[0] = 4U;
    block[3] = 2U;
    result = gsdc_diag_decode(&layout, block, 4U, &kind, &node, &code);
    CHECK(result.fault == GSDC_DIAG_CODE && result.kind == 1U && result.value == 2U);
    block[1] = 2U;
    result = gsdc_diag_decode(&layout, block, 4U, &kind, &node, &code);
    CHECK(result.fault == GSDC_DIAG_TYPE && result.value == 2U);
    block[1] = 1U;
    block[2] = 8U;
    result = gsdc_diag_decode(&layout, block, 4U, &kind, &node, &code);
    CHECK(result.fault == GSDC_DIAG_NODE && result.value == 8U);
    /* The header says 2 bytes: no room for the node. */
    block[0] = 2U;
    result = gsdc_diag_decode(&layout, block, 4U, &kind, &node, &code);
    CHECK(result.fault == GSDC_DIAG_SHORT && result.expected == 3U && result.found == 2U);
    /* The header says 4 bytes; 3 came. */
    block[0] = 4U;
    result = gsdc_diag_decode(&layout, block, 3U, &kind, &node, &code);
    CHECK(result.fault == GSDC_DIAG_SHORT && result.expected == 4U && result.found == 3U);
    CHECK(kind == 1U && node == 7U && code == 3U); /* untouched by the refusals */
}

/* A block whose code is not right after the node: the byte between is 0. */
static void an_encoded_block_is_0_where_it_holds_nothing(void)
{
    static const gsdc_diag_type_t types[1] = {{1U, 5U, code_three}};
    static const uint8_t expected[5] = {5U, 1U, 6U, 0U, 3U};
    gsdc_diag_layout_t layout = small_diag();
    /* Room for a 16-bit code at byte 4, which compilers see the encoder
     * could write, though this layout's one type has a one-byte code. */
    uint8_t block[6] = {0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU};
    size_t len = 0U;
    layout.code_at = 4U;
    layout.types = types;
    layout.type_count = 1U;
    CHECK(gsdc_diag_encode(&layout, 1U, 6U, 3U, block, &len).fault == GSDC_DIAG_OK);
    CHECK(len == 5U && same_bytes(block, expected, 5U) && block[5] == 0xEEU);
}

static const test_t tests[] = {
    {"words_are_big_endian", words_are_big_endian},
    {"bit_fields_read_and_write_their_bits_only", bit_fields_read_and_write_their_bits_only},
    {"values_are_read_and_checked_at_their_offset", values_are_read_and_checked_at_their_offset},
    {"byte_and_word_entries_are_read_each_at_its_offset",
     byte_and_word_entries_are_read_each_at_its_offset},
    {"a_record_ends_with_its_fail_safe_values", a_record_ends_with_its_fail_safe_values},
    {"an_access_point_record_reads_whole_values_and_bits",
     an_access_point_record_reads_whole_values_and_bits},
    {"reading_past_the_end_is_refused", reading_past_the_end_is_refused},
    {"pke_no_request_ignores_what_the_master_left", pke_no_request_ignores_what_the_master_left},
    {"pke_reserved_bits_are_not_read_and_written_0",
     pke_reserved_bits_are_not_read_and_written_0},
    {"pke_codes_the_manual_does_not_define_are_refused",
     pke_codes_the_manual_does_not_define_are_refused},
    {"profidrive_words_in_pwe2_double_words_across_both",
     profidrive_words_in_pwe2_double_words_across_both},
    {"profidrive_the_subindex_is_the_high_byte_of_ind",
     profidrive_the_subindex_is_the_high_byte_of_ind},
    {"profidrive_ids_beyond_the_profile_are_refused", profidrive_ids_beyond_the_profile_are_refused},
    {"profidrive_encoders_refuse_what_the_channel_cannot_carry",
     profidrive_encoders_refuse_what_the_channel_cannot_carry},
    {"profidrive_no_request_ignores_what_the_master_left",
     profidrive_no_request_ignores_what_the_master_left},
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
    {"bit_areas_share_a_byte", bit_areas_share_a_byte},
    {"bits_beyond_the_range_are_refused", bits_beyond_the_range_are_refused},
    {"unsigned16_is_big_endian_and_within_a_byte_s_values",
     unsigned16_is_big_endian_and_within_a_byte_s_values},
    {"a_field_past_the_end_is_a_length_error", a_field_past_the_end_is_a_length_error},
    {"config_bytes_of_no_module_are_refused", config_bytes_of_no_module_are_refused},
    {"totals_count_the_nodes_in_use_within_the_limits",
     totals_count_the_nodes_in_use_within_the_limits},
    {"a_count_past_the_nodes_is_refused", a_count_past_the_nodes_is_refused},
    {"data_offsets_follow_the_nodes_in_use", data_offsets_follow_the_nodes_in_use},
    {"nodes_read_and_write_in_order", nodes_read_and_write_in_order},
    {"diagnosis_blocks_are_read_as_long_as_their_header_says",
     diagnosis_blocks_are_read_as_long_as_their_header_says},
    {"an_encoded_block_is_0_where_it_holds_nothing", an_encoded_block_is_0_where_it_holds_nothing},
};

int main(void)
{
    return run_tests(tests, sizeof tests / sizeof tests[0]);
}
