/* The manuals' telegram examples, byte for byte, through the generated C
 * layouts: decoded with the layouts' names and encoded back. The same
 * examples as the Rust firmware crate's tests/firmware/tests/manuals.rs,
 * and what C adds: encoders that refuse what the manuals call illegal.
 *
 * tests/c_header.rs compiles it as C and as C++, runs it, and compares the
 * tests it names with the list it expects. It defines GSD_MAX_USER_PRM_DATA_LEN
 * and GSD_MAX_DIAG_DATA_LEN from the GSD generated beside the MD810 layout,
 * and GSD_GW_* from the one beside the MD810 gateway's (MD810GW.GSD). The
 * PROFIdrive tests use the layout of tests/fixtures/valid/profidrive.toml. */
#include "md810dp_layout.h"
#include "mv810_pnet02_layout.h"
#include "9kdp1_layout.h"
#include "md810_gateway_layout.h"
#include "profidrive_layout.h"

#include "harness.h"

/* A telegram of a manual's worked example: the description, the manual's
 * section, the bytes as it prints them, the PKW codec that reads them,
 * whether it goes out (master to drive), and its PKW words. */
typedef enum { EXAMPLE_PKE, EXAMPLE_STATION } example_codec_t;
typedef struct {
    const char *description;
    const char *section;
    const char *printed;
    example_codec_t codec;
    bool out;
    uint8_t pkw[GSDC_PKW_BYTES];
} example_t;

#include "examples.h"

#ifndef GSD_MAX_USER_PRM_DATA_LEN
#error "the test defines GSD_MAX_USER_PRM_DATA_LEN from MD810DP.GSD"
#endif
#ifndef GSD_MAX_DIAG_DATA_LEN
#error "the test defines GSD_MAX_DIAG_DATA_LEN from MD810DP.GSD"
#endif
#if !defined(GSD_GW_MAX_USER_PRM_DATA_LEN) || !defined(GSD_GW_MAX_DIAG_DATA_LEN) || \
    !defined(GSD_GW_MAX_INPUT_LEN) || !defined(GSD_GW_MAX_OUTPUT_LEN) || \
    !defined(GSD_GW_MAX_MODULE) || !defined(GSD_GW_MODULE_CONFIGS)
#error "the test defines GSD_GW_* from MD810GW.GSD"
#endif

static bool same_values(const uint16_t *a, const uint16_t *b, size_t count)
{
    size_t i;
    for (i = 0U; i < count; i++) {
        if (a[i] != b[i]) {
            return false;
        }
    }
    return true;
}

/* ------------------------------------------------------------------------
 * MD810 */

/* F0-08, by the manual's numbering (1.4.1): 0xFxyy. */
#define F0_08 0xF008U

/* A PPO1 telegram carrying `pkw` and the PZD words 0001 1388. */
static void ppo1(const char *pkw, uint8_t telegram[MD810DP_PPO1_BYTES])
{
    uint8_t pzd[4];
    words(pkw, telegram, GSDC_PKW_BYTES);
    words("0001 1388", pzd, sizeof pzd);
    gsdc_copy_bytes(&telegram[MD810DP_PPO1_PZD_OFFSET], pzd, sizeof pzd);
}

/* Manual 1.4.2, figure 6: the master reads F0-08. */
static void md810_read_f0_08(void)
{
    md810dp_ppo1_out_t out;
    gsdc_pke_request_t request;
    uint8_t again[MD810DP_PPO1_BYTES] = {0};
    ppo1("10F0 0800 0000 0000", out.bytes);
    CHECK(gsdc_pke_request_decode(out.bytes, &request) == GSDC_PKW_OK);
    CHECK(request.command == GSDC_PKE_READ);
    CHECK(request.address == F0_08);
    CHECK(gsdc_word_get(&out.bytes[MD810DP_PPO1_PZD_OFFSET], 0U) == 0x0001U);
    CHECK(gsdc_word_get(&out.bytes[MD810DP_PPO1_PZD_OFFSET], 1U) == 0x1388U);
    CHECK(gsdc_pke_request_encode(&request, again) == GSDC_PKW_OK);
    CHECK(same_bytes(again, out.bytes, GSDC_PKW_BYTES));
}

/* Figure 6: the drive answers 5000, 50.00 Hz. */
static void md810_answer_50_hz(void)
{
    md810dp_ppo1_in_t answer;
    md810dp_ppo1_in_t sent;
    gsdc_pke_response_t response;
    gsdc_pke_response_t done;
    ppo1("10F0 0800 0000 1388", answer.bytes);
    CHECK(gsdc_pke_response_decode(answer.bytes, &response) == GSDC_PKW_OK);
    CHECK(response.code == GSDC_PKE_DONE);
    CHECK(response.address == F0_08);
    CHECK(response.value == 5000U);
    done.code = GSDC_PKE_DONE;
    done.address = F0_08;
    done.value = 5000U;
    sent = answer;
    words("FFFF FFFF FFFF FFFF", sent.bytes, GSDC_PKW_BYTES);
    CHECK(gsdc_pke_response_encode(&done, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, answer.bytes, MD810DP_PPO1_BYTES));
}

/* Figure 7: the master writes 20.00 Hz to F0-08. */
static void md810_write_20_hz(void)
{
    md810dp_ppo1_out_t out;
    md810dp_ppo1_out_t sent;
    gsdc_pke_request_t request;
    gsdc_pke_request_t write;
    ppo1("20F0 0800 0000 07D0", out.bytes);
    CHECK(gsdc_pke_request_decode(out.bytes, &request) == GSDC_PKW_OK);
    CHECK(request.command == GSDC_PKE_WRITE);
    CHECK(request.address == F0_08);
    CHECK(request.value == 2000U);
    write.command = GSDC_PKE_WRITE;
    write.address = F0_08;
    write.value = 2000U;
    sent = out;
    CHECK(gsdc_pke_request_encode(&write, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, out.bytes, MD810DP_PPO1_BYTES));
}

/* Figures 6 and 7: "cannot execute", with error codes 1 to 4. */
static void md810_error_answers(void)
{
    static const char *const telegrams[4] = {
        "70F0 0800 0000 0001",
        "70F0 0800 0000 0002",
        "70F0 0800 0000 0003",
        "70F0 0800 0000 0004",
    };
    static const uint16_t errors[4] = {
        GSDC_PKE_ERROR_ILLEGAL_COMMAND,
        GSDC_PKE_ERROR_ILLEGAL_ADDRESS,
        GSDC_PKE_ERROR_ILLEGAL_DATA,
        GSDC_PKE_ERROR_OTHER,
    };
    size_t i;
    for (i = 0U; i < 4U; i++) {
        md810dp_ppo1_in_t answer;
        md810dp_ppo1_in_t sent;
        gsdc_pke_response_t failed;
        gsdc_pke_response_t decoded;
        ppo1(telegrams[i], answer.bytes);
        failed.code = GSDC_PKE_CANNOT_EXECUTE;
        failed.address = F0_08;
        failed.value = errors[i];
        CHECK(gsdc_pke_response_decode(answer.bytes, &decoded) == GSDC_PKW_OK);
        CHECK(decoded.code == failed.code);
        CHECK(decoded.address == failed.address);
        CHECK(decoded.value == failed.value);
        sent = answer;
        CHECK(gsdc_pke_response_encode(&failed, sent.bytes) == GSDC_PKW_OK);
        CHECK(same_bytes(sent.bytes, answer.bytes, MD810DP_PPO1_BYTES));
    }
}

/* Commands and codes the manual does not define are refused both ways; an
 * encoder that refuses writes nothing. */
static void md810_illegal_telegrams_are_refused(void)
{
    uint8_t telegram[MD810DP_PPO1_BYTES];
    uint8_t untouched[GSDC_PKW_BYTES] = {1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U};
    uint8_t pkw[GSDC_PKW_BYTES] = {1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U};
    gsdc_pke_request_t request;
    gsdc_pke_response_t response;
    ppo1("30F0 0800 0000 0000", telegram);
    CHECK(gsdc_pke_request_decode(telegram, &request) == GSDC_PKW_BAD_COMMAND);
    CHECK(request.command == 3U);
    CHECK(request.address == F0_08);
    ppo1("70F0 0800 0000 0009", telegram);
    CHECK(gsdc_pke_response_decode(telegram, &response) == GSDC_PKW_BAD_ERROR_CODE);
    CHECK(response.value == 9U);
    ppo1("20F0 0800 0000 0009", telegram);
    CHECK(gsdc_pke_response_decode(telegram, &response) == GSDC_PKW_BAD_RESPONSE);
    CHECK(gsdc_pke_request_encode(&request, pkw) == GSDC_PKW_BAD_COMMAND);
    response.code = GSDC_PKE_CANNOT_EXECUTE;
    response.value = 5U;
    CHECK(gsdc_pke_response_encode(&response, pkw) == GSDC_PKW_BAD_ERROR_CODE);
    response.code = 2U;
    CHECK(gsdc_pke_response_encode(&response, pkw) == GSDC_PKW_BAD_RESPONSE);
    CHECK(same_bytes(pkw, untouched, GSDC_PKW_BYTES));
}

/* MD810's PPO5: the PKW and 12 PZD words, 32 bytes (1.3.1). */
static void md810_ppo5_is_32_bytes(void)
{
    md810dp_ppo5_out_t out;
    md810dp_ppo5_out_t sent;
    gsdc_pke_request_t request;
    size_t i;
    words("10F0 0800 0000 0000 0001 0002 0003 0004 0005 0006 0007 0008 0009 000A 000B 000C",
          out.bytes, sizeof out.bytes);
    CHECK(sizeof(md810dp_ppo5_out_t) == 32U);
    CHECK(sizeof(md810dp_ppo5_in_t) == 32U);
    CHECK(MD810DP_PPO5_PZD_WORDS == 12U);
    CHECK(gsdc_pke_request_decode(out.bytes, &request) == GSDC_PKW_OK);
    CHECK(request.command == GSDC_PKE_READ);
    CHECK(request.address == F0_08);
    for (i = 0U; i < MD810DP_PPO5_PZD_WORDS; i++) {
        CHECK(gsdc_word_get(&out.bytes[MD810DP_PPO5_PZD_OFFSET], i) == i + 1U);
    }
    CHECK(gsdc_pke_request_encode(&request, sent.bytes) == GSDC_PKW_OK);
    for (i = 0U; i < MD810DP_PPO5_PZD_WORDS; i++) {
        gsdc_word_put(&sent.bytes[MD810DP_PPO5_PZD_OFFSET], i, (uint16_t)(i + 1U));
    }
    CHECK(same_bytes(sent.bytes, out.bytes, MD810DP_PPO5_BYTES));
}

/* The config identifiers of the PPO table (FIELDBUS-NOTES section 1). */
static void md810_ppo_config_bytes(void)
{
    static const uint8_t ppo1_config[MD810DP_PPO1_CONFIG_LEN] = MD810DP_PPO1_CONFIG;
    static const uint8_t ppo2_config[MD810DP_PPO2_CONFIG_LEN] = MD810DP_PPO2_CONFIG;
    static const uint8_t ppo3_config[MD810DP_PPO3_CONFIG_LEN] = MD810DP_PPO3_CONFIG;
    static const uint8_t ppo4_config[MD810DP_PPO4_CONFIG_LEN] = MD810DP_PPO4_CONFIG;
    static const uint8_t ppo5_config[MD810DP_PPO5_CONFIG_LEN] = MD810DP_PPO5_CONFIG;
    static const uint8_t f3f1[2] = {0xF3U, 0xF1U};
    static const uint8_t f3f5[2] = {0xF3U, 0xF5U};
    static const uint8_t f3fb[2] = {0xF3U, 0xFBU};
    CHECK(same_bytes(ppo1_config, f3f1, 2U));
    CHECK(same_bytes(ppo2_config, f3f5, 2U));
    CHECK(ppo3_config[0] == 0xF1U);
    CHECK(ppo4_config[0] == 0xF5U);
    CHECK(same_bytes(ppo5_config, f3fb, 2U));
}

/* The parameter telegram with the GSD's defaults: the DPV1 status bytes,
 * then F0-00 for each of PZD1..12 out, PZD1..12 in and Index0..5 (1.6). */
static void md810_default_user_prm_is_f0_00_everywhere(void)
{
    static const uint8_t dpv1_status[3] = MD810DP_USER_PRM_DPV1_STATUS;
    static const uint16_t pzd_out[MD810DP_PZD_OUT_COUNT] = MD810DP_PZD_OUT_DEFAULTS;
    static const uint16_t pzd_in[MD810DP_PZD_IN_COUNT] = MD810DP_PZD_IN_DEFAULTS;
    static const uint16_t dpv1_index[MD810DP_DPV1_INDEX_COUNT] = MD810DP_DPV1_INDEX_DEFAULTS;
    uint8_t telegram[MD810DP_USER_PRM_LEN] = {0};
    md810dp_user_prm_t prm;
    size_t i;
    CHECK(MD810DP_USER_PRM_LEN == GSD_MAX_USER_PRM_DATA_LEN);
    for (i = 0U; i < 30U; i++) {
        gsdc_u16be_put(&telegram[3U + 2U * i], 0xF000U);
    }
    CHECK(md810dp_decode_user_prm(telegram, sizeof telegram, &prm).fault == GSDC_PRM_OK);
    CHECK(same_bytes(prm.dpv1_status, dpv1_status, 3U));
    for (i = 0U; i < MD810DP_PZD_OUT_COUNT; i++) {
        CHECK(prm.pzd_out[i] == 0xF000U);
        CHECK(prm.pzd_in[i] == 0xF000U);
    }
    CHECK(prm.dpv1_index[5] == 0xF000U);
    CHECK(same_values(prm.pzd_out, pzd_out, MD810DP_PZD_OUT_COUNT));
    CHECK(same_values(prm.pzd_in, pzd_in, MD810DP_PZD_IN_COUNT));
    CHECK(same_values(prm.dpv1_index, dpv1_index, MD810DP_DPV1_INDEX_COUNT));
}

/* The manual's example (1.6 step 5): Index0 = F0-02, Index1 = F0-08; a
 * telegram one byte short is refused and leaves the decoded one as it was. */
static void md810_user_prm_maps_dpv1_indexes(void)
{
    uint8_t telegram[MD810DP_USER_PRM_LEN] = {0};
    md810dp_user_prm_t prm;
    gsdc_prm_result_t result;
    words("F002 F008", &telegram[MD810DP_DPV1_INDEX_USER_PRM_OFFSET], 4U);
    CHECK(md810dp_decode_user_prm(telegram, sizeof telegram, &prm).fault == GSDC_PRM_OK);
    CHECK(prm.dpv1_index[0] == 0xF002U);
    CHECK(prm.dpv1_index[1] == 0xF008U);
    CHECK(prm.dpv1_index[2] == 0U);
    result = md810dp_decode_user_prm(&telegram[1], sizeof telegram - 1U, &prm);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(result.expected == 63U);
    CHECK(result.found == 62U);
    CHECK(prm.dpv1_index[1] == 0xF008U);
}

/* Manual 1.8: when the card loses the drive the device-related diagnosis
 * is header 3, then 0x00 0x34; the GSD's Max_Diag_Data_Len is the 6
 * standard bytes and this block. */
static void md810_card_lost_the_drive_diagnosis(void)
{
    uint8_t block[MD810DP_DIAGNOSIS_LEN] = MD810DP_DIAGNOSIS_EMPTY;
    static const uint8_t expected[3] = {0x03U, 0x00U, 0x34U};
    uint16_t value;
    gsdc_diag_area_set(block, sizeof block, MD810DP_DIAGNOSIS_BITS_8_15_FIRST,
                       MD810DP_DIAGNOSIS_BITS_8_15_LAST,
                       MD810DP_DIAGNOSIS_BITS_8_TO_15_DP_CARD_DRIVE_COMM_INTERRUPTED);
    CHECK(same_bytes(block, expected, 3U));
    value = gsdc_diag_area_get(block, sizeof block, MD810DP_DIAGNOSIS_BITS_8_15_FIRST,
                               MD810DP_DIAGNOSIS_BITS_8_15_LAST);
    CHECK(value == MD810DP_DIAGNOSIS_BITS_8_TO_15_DP_CARD_DRIVE_COMM_INTERRUPTED);
    CHECK(md810dp_diagnosis_bits_8_to_15_is_value(value));
    CHECK(!md810dp_diagnosis_bits_8_to_15_is_value(0x35U));
    CHECK(6U + MD810DP_DIAGNOSIS_LEN == GSD_MAX_DIAG_DATA_LEN);
}

/* The DPV1 indexes as a PROFINET record: 12 bytes, each value checked. */
static void md810_dpv1_indexes_as_a_profinet_record(void)
{
    uint8_t record[MD810DP_DPV1_INDEX_RECORD_LEN];
    uint16_t values[MD810DP_DPV1_INDEX_COUNT] = {0};
    static const uint16_t expected[MD810DP_DPV1_INDEX_COUNT] = {0xF002U, 0xF008U, 0xF000U,
                                                                0xF000U, 0xF000U, 0xF000U};
    CHECK(MD810DP_DPV1_INDEX_RECORD_LEN == 12U);
    words("F002 F008 F000 F000 F000 F000", record, sizeof record);
    CHECK(md810dp_dpv1_index_decode_record(record, sizeof record, values).fault == GSDC_PRM_OK);
    CHECK(same_values(values, expected, MD810DP_DPV1_INDEX_COUNT));
    CHECK(md810dp_dpv1_index_decode_record(&record[2], sizeof record - 2U, values).fault ==
          GSDC_PRM_LENGTH);
}

/* ------------------------------------------------------------------------
 * MV810 */

/* Section 3: the PN master reads P43.02 of the drive with the card, station
 * 1, through a 12-PZD telegram with the PKW channel; the drive answers 1,
 * PZD2 carries the frequency reference. */
static void mv810_read_p43_02(void)
{
    mv810_pnet02_pkw_pzd12_out_t out = {{0}};
    mv810_pnet02_pkw_pzd12_out_t sent = {{0}};
    mv810_pnet02_pkw_pzd12_in_t answer = {{0}};
    mv810_pnet02_pkw_pzd12_in_t reply = {{0}};
    gsdc_station_request_t request;
    gsdc_station_response_t response;
    CHECK(MV810_PNET02_PZD_OUT_2_PARAMETER == 0x2B02U);
    words("0100 0003 2B02 0001", out.bytes, GSDC_PKW_BYTES);
    CHECK(gsdc_station_request_decode(out.bytes, &request) == GSDC_PKW_OK);
    CHECK(request.target == 1U);
    CHECK(request.source == 0U);
    CHECK(request.command == GSDC_STATION_READ);
    CHECK(request.address == MV810_PNET02_PZD_OUT_2_PARAMETER);
    CHECK(gsdc_station_request_encode(&request, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, out.bytes, MV810_PNET02_PKW_PZD12_BYTES));

    words("0001 0003 2B02 0001", answer.bytes, GSDC_PKW_BYTES);
    CHECK(gsdc_station_response_decode(answer.bytes, &response) == GSDC_PKW_OK);
    CHECK(!response.failed);
    CHECK(response.command == GSDC_STATION_READ);
    CHECK(response.value == MV810_PNET02_PZD_OUT_CHOICE_FREQUENCY_REFERENCE);
    CHECK(gsdc_station_response_encode(&response, reply.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(reply.bytes, answer.bytes, MV810_PNET02_PKW_PZD12_BYTES));
}

/* Section 3: write P43.02 = 1, once without storing it (0x07), once into
 * EEPROM (0x06); the drive replies with the command and value 0. */
static void mv810_write_p43_02(void)
{
    static const char *const requests[2] = {"0100 0007 2B02 0001 0001",
                                            "0100 0006 2B02 0001 0001"};
    static const char *const replies[2] = {"0001 0007 2B02 0000 0000",
                                           "0001 0006 2B02 0000 0000"};
    static const uint16_t commands[2] = {GSDC_STATION_WRITE, GSDC_STATION_WRITE_AND_STORE};
    size_t i;
    for (i = 0U; i < 2U; i++) {
        mv810_pnet02_pkw_pzd1_out_t out;
        mv810_pnet02_pkw_pzd1_in_t answer;
        mv810_pnet02_pkw_pzd1_in_t sent;
        gsdc_station_request_t request;
        gsdc_station_response_t response;
        words(requests[i], out.bytes, sizeof out.bytes);
        CHECK(gsdc_station_request_decode(out.bytes, &request) == GSDC_PKW_OK);
        CHECK(request.command == commands[i]);
        CHECK(request.address == MV810_PNET02_PZD_OUT_2_PARAMETER);
        CHECK(request.value == 1U);
        words(replies[i], answer.bytes, sizeof answer.bytes);
        CHECK(gsdc_station_response_decode(answer.bytes, &response) == GSDC_PKW_OK);
        CHECK(response.command == commands[i]);
        CHECK(!response.failed);
        CHECK(response.address == MV810_PNET02_PZD_OUT_2_PARAMETER);
        sent = answer;
        response.value = 0x1234U; /* not written after a write */
        CHECK(gsdc_station_response_encode(&response, sent.bytes) == GSDC_PKW_OK);
        CHECK(same_bytes(sent.bytes, answer.bytes, MV810_PNET02_PKW_PZD1_BYTES));
    }
}

/* Section 3: an error reply is 0x80 + the command; as a request it is not
 * one the manual defines, nor is a read of two parameters. */
static void mv810_error_reply(void)
{
    mv810_pnet02_pkw_pzd1_in_t answer;
    mv810_pnet02_pkw_pzd1_in_t sent;
    uint8_t untouched[GSDC_PKW_BYTES] = {0};
    uint8_t pkw[GSDC_PKW_BYTES] = {0};
    gsdc_station_response_t response;
    gsdc_station_request_t request;
    words("0001 0087 2B02 0003 0000", answer.bytes, sizeof answer.bytes);
    CHECK(gsdc_station_response_decode(answer.bytes, &response) == GSDC_PKW_OK);
    CHECK(response.failed);
    CHECK(response.command == GSDC_STATION_WRITE);
    CHECK(response.value == 3U);
    sent = answer;
    CHECK(gsdc_station_response_encode(&response, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, answer.bytes, MV810_PNET02_PKW_PZD1_BYTES));
    CHECK(gsdc_station_request_decode(answer.bytes, &request) == GSDC_PKW_BAD_COMMAND);
    CHECK(request.command == 0x87U);
    CHECK(gsdc_station_request_encode(&request, pkw) == GSDC_PKW_BAD_COMMAND);
    words("0100 0003 2B02 0002", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_request_decode(pkw, &request) == GSDC_PKW_BAD_READ_COUNT);
    words("0001 0005 2B02 0000", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_response_decode(pkw, &response) == GSDC_PKW_BAD_COMMAND);
    response.command = 0x05U;
    words("0000 0000 0000 0000", pkw, GSDC_PKW_BYTES);
    CHECK(gsdc_station_response_encode(&response, pkw) == GSDC_PKW_BAD_COMMAND);
    CHECK(same_bytes(pkw, untouched, GSDC_PKW_BYTES));
}

/* Section 3, PZD1: control word bits and the status word's control mode. */
static void mv810_control_and_status_words(void)
{
    uint16_t status = 0x0421U; /* forward running, ready, communication */
    CHECK((MV810_PNET02_CONTROL_WORD_FORWARD_RUNNING_MASK |
           MV810_PNET02_CONTROL_WORD_FAULT_RESET_MASK) == 0x0041U);
    CHECK(gsdc_field_get(status, MV810_PNET02_STATUS_WORD_FORWARD_RUNNING_MASK,
                         MV810_PNET02_STATUS_WORD_FORWARD_RUNNING_SHIFT) == 1U);
    CHECK(gsdc_field_get(status, MV810_PNET02_STATUS_WORD_READY_STATUS_MASK,
                         MV810_PNET02_STATUS_WORD_READY_STATUS_SHIFT) == 1U);
    CHECK(gsdc_field_get(status, MV810_PNET02_STATUS_WORD_CONTROL_MODE_MASK,
                         MV810_PNET02_STATUS_WORD_CONTROL_MODE_SHIFT) ==
          MV810_PNET02_STATUS_WORD_CONTROL_MODE_COMMUNICATION);
    CHECK(gsdc_field_with(status, MV810_PNET02_STATUS_WORD_CONTROL_MODE_MASK,
                          MV810_PNET02_STATUS_WORD_CONTROL_MODE_SHIFT,
                          MV810_PNET02_STATUS_WORD_CONTROL_MODE_TERMINAL) == 0x0221U);
    CHECK(gsdc_field_get(status, MV810_PNET02_STATUS_WORD_MOTOR_TYPE_MASK,
                         MV810_PNET02_STATUS_WORD_MOTOR_TYPE_SHIFT) ==
          MV810_PNET02_STATUS_WORD_MOTOR_TYPE_ASYNCHRONOUS);
    CHECK(mv810_pnet02_status_word_control_mode_is_value(2U));
    CHECK(!mv810_pnet02_status_word_control_mode_is_value(3U));
}

static void mv810_standard_telegram_1_is_two_words(void)
{
    mv810_pnet02_telegram1_out_t out;
    words("047F 4000", out.bytes, sizeof out.bytes);
    CHECK(sizeof out == 4U);
    CHECK(MV810_PNET02_TELEGRAM1_PZD_OFFSET == 0U);
    CHECK(gsdc_word_get(out.bytes, 1U) == 0x4000U);
    CHECK(MV810_PNET02_TELEGRAM1_IDENT == 0x10UL);
}

/* The PZD mappings are P43.02..P43.12 (out) and P43.13..P43.23 (in), each
 * value one of section 3's choices (15 is reserved); P43.01 the message
 * type. Section 4 sets them at the drive: no module carries a parameter
 * record, and the controller writes nothing at startup. */
static void mv810_mappings_set_at_the_drive(void)
{
    static const uint16_t parameters[11] = {
        MV810_PNET02_PZD_OUT_2_PARAMETER,  MV810_PNET02_PZD_OUT_3_PARAMETER,
        MV810_PNET02_PZD_OUT_4_PARAMETER,  MV810_PNET02_PZD_OUT_5_PARAMETER,
        MV810_PNET02_PZD_OUT_6_PARAMETER,  MV810_PNET02_PZD_OUT_7_PARAMETER,
        MV810_PNET02_PZD_OUT_8_PARAMETER,  MV810_PNET02_PZD_OUT_9_PARAMETER,
        MV810_PNET02_PZD_OUT_10_PARAMETER, MV810_PNET02_PZD_OUT_11_PARAMETER,
        MV810_PNET02_PZD_OUT_12_PARAMETER,
    };
    static const uint16_t settings_defaults[MV810_PNET02_SETTINGS_COUNT] =
        MV810_PNET02_SETTINGS_DEFAULTS;
    const gsdc_pn_device_t *device = mv810_pnet02_pn_device();
    size_t i;
    for (i = 0U; i < 11U; i++) {
        CHECK(parameters[i] == 0x2B02U + i);
    }
    CHECK(MV810_PNET02_PZD_IN_2_PARAMETER == 0x2B0DU);
    CHECK(mv810_pnet02_pzd_out_allowed(MV810_PNET02_PZD_OUT_CHOICE_FREQUENCY_REFERENCE));
    CHECK(mv810_pnet02_pzd_out_allowed(14U));
    CHECK(!mv810_pnet02_pzd_out_allowed(15U));
    CHECK(mv810_pnet02_pzd_in_allowed(25U));
    CHECK(!mv810_pnet02_pzd_in_allowed(26U));
    CHECK(mv810_pnet02_settings_allowed(MV810_PNET02_SETTINGS_CHOICE_USER_DEFINED_MESSAGE));
    CHECK(settings_defaults[0] == 1U);
    CHECK(device->modules_count == 13U);
    for (i = 0U; i < device->modules_count; i++) {
        CHECK(device->modules[i].records == NULL);
        CHECK(device->modules[i].records_count == 0U);
    }
}

/* Every telegram of every worked example the descriptions give
 * ([[examples]], written into examples.h): decoded by the layout's PKW codec
 * (a request out, a response in) and encoded back byte for byte. MD810's
 * are 1.4.2's read and write of F0-08, each answered done or failed with
 * one of four error codes: 12 telegrams. */
static void every_example_of_the_manuals_round_trips(void)
{
    size_t i;
    CHECK(EXAMPLE_TELEGRAMS == 12U);
    for (i = 0U; i < EXAMPLE_TELEGRAMS; i++) {
        const example_t *e = &examples[i];
        uint8_t again[GSDC_PKW_BYTES] = {0};
        if (e->codec == EXAMPLE_PKE && e->out) {
            gsdc_pke_request_t request;
            CHECK(gsdc_pke_request_decode(e->pkw, &request) == GSDC_PKW_OK);
            CHECK(gsdc_pke_request_encode(&request, again) == GSDC_PKW_OK);
        } else if (e->codec == EXAMPLE_PKE) {
            gsdc_pke_response_t response;
            CHECK(gsdc_pke_response_decode(e->pkw, &response) == GSDC_PKW_OK);
            CHECK(gsdc_pke_response_encode(&response, again) == GSDC_PKW_OK);
        } else if (e->out) {
            gsdc_station_request_t request;
            CHECK(gsdc_station_request_decode(e->pkw, &request) == GSDC_PKW_OK);
            CHECK(gsdc_station_request_encode(&request, again) == GSDC_PKW_OK);
        } else {
            gsdc_station_response_t response;
            CHECK(gsdc_station_response_decode(e->pkw, &response) == GSDC_PKW_OK);
            CHECK(gsdc_station_response_encode(&response, again) == GSDC_PKW_OK);
        }
        CHECK(same_bytes(again, e->pkw, GSDC_PKW_BYTES));
    }
}

/* ------------------------------------------------------------------------
 * PI9000 (9KDP1) */

/* Appendix I-3: command 1 is forward run; the card sends it in PZD1. */
static void pi9000_command_word_in_ppo3(void)
{
    gsdc_9kdp1_ppo3_out_t out;
    gsdc_9kdp1_ppo4_in_t in = {{0}};
    gsdc_9kdp1_ppo4_in_t zero = {{0}};
    uint16_t command;
    words("0001 1388", out.bytes, sizeof out.bytes);
    command = gsdc_field_get(gsdc_word_get(&out.bytes[GSDC_9KDP1_PPO3_PZD_OFFSET], 0U),
                             GSDC_9KDP1_CONTROL_WORD_COMMAND_FUNCTION_MASK,
                             GSDC_9KDP1_CONTROL_WORD_COMMAND_FUNCTION_SHIFT);
    CHECK(command == GSDC_9KDP1_CONTROL_WORD_COMMAND_FUNCTION_FORWARD_RUN);
    CHECK(gsdc_9kdp1_control_word_command_function_is_value(command));
    CHECK(GSDC_9KDP1_CONTROL_WORD_COMMAND_FUNCTION_FAULT_RESET == 7U);
    CHECK(gsdc_9kdp1_status_word_status_word_function_is_value(3U));
    CHECK(GSDC_9KDP1_STATUS_WORD_STATUS_WORD_FUNCTION_STOP == 3U);
    CHECK(same_bytes(in.bytes, zero.bytes, GSDC_9KDP1_PPO4_BYTES));
}

/* Appendix I: the fault code of 0x8000 in the diagnosis' low byte. */
static void pi9000_fault_code_diagnosis(void)
{
    uint8_t block[GSDC_9KDP1_DIAGNOSIS_LEN] = GSDC_9KDP1_DIAGNOSIS_EMPTY;
    static const uint8_t expected[3] = {0x03U, 0x00U, 11U};
    gsdc_diag_area_set(block, sizeof block, GSDC_9KDP1_DIAGNOSIS_BITS_8_15_FIRST,
                       GSDC_9KDP1_DIAGNOSIS_BITS_8_15_LAST,
                       GSDC_9KDP1_DIAGNOSIS_BITS_8_TO_15_MOTOR_OVERLOAD);
    CHECK(same_bytes(block, expected, 3U));
    CHECK(gsdc_9kdp1_diagnosis_bits_8_to_15_is_value(0x0BU));
    CHECK(!gsdc_9kdp1_diagnosis_bits_8_to_15_is_value(24U));
}

/* Without DPV1 the parameter telegram is the mappings alone: PZD2..6 each
 * way, with appendix I's addresses as defaults. */
static void pi9000_default_user_prm(void)
{
    static const uint16_t pzd_out[GSDC_9KDP1_PZD_OUT_COUNT] = GSDC_9KDP1_PZD_OUT_DEFAULTS;
    static const uint16_t pzd_in[GSDC_9KDP1_PZD_IN_COUNT] = GSDC_9KDP1_PZD_IN_DEFAULTS;
    uint8_t telegram[GSDC_9KDP1_USER_PRM_LEN];
    gsdc_9kdp1_user_prm_t prm;
    CHECK(GSDC_9KDP1_USER_PRM_LEN == 20U);
    words("1000 2001 2002 2003 2004 1001 1002 1004 8000 8001", telegram, sizeof telegram);
    CHECK(gsdc_9kdp1_decode_user_prm(telegram, sizeof telegram, &prm).fault == GSDC_PRM_OK);
    CHECK(same_values(prm.pzd_out, pzd_out, GSDC_9KDP1_PZD_OUT_COUNT));
    CHECK(same_values(prm.pzd_in, pzd_in, GSDC_9KDP1_PZD_IN_COUNT));
    CHECK(GSDC_9KDP1_PZD_IN_5_DEFAULT == 0x8000U);
}

/* ------------------------------------------------------------------------
 * MD810 bridge mode (chapter 2): DP to CANopen, through the gateway layout */

/* A configuration of `count` slaves with `inputs` TPDO (input) and
 * `outputs` RPDO (output) words, slave 1 first; the other slaves none. */
static md810_gateway_node_config_t bridge_config(uint8_t count, const uint8_t *input,
                                                 size_t inputs, const uint8_t *output,
                                                 size_t outputs)
{
    md810_gateway_node_config_t config = MD810_GATEWAY_NODE_CONFIG_DEFAULT;
    size_t i;
    config.node_count = count;
    for (i = 0U; i < inputs; i++) {
        config.input_words[i] = input[i];
    }
    for (i = 0U; i < outputs; i++) {
        config.output_words[i] = output[i];
    }
    return config;
}

/* 2.4 step 5's example: RPDO 64 words, TPDO 120 words; 15 slaves of 8 TPDO
 * words (2.2.1's most), the first 8 of them with 8 RPDO words. */
static md810_gateway_node_config_t bridge_manual_example(void)
{
    static const uint8_t eights[15] = {8U, 8U, 8U, 8U, 8U, 8U, 8U, 8U,
                                       8U, 8U, 8U, 8U, 8U, 8U, 8U};
    return bridge_config(15U, eights, 15U, eights, 8U);
}

/* 30 slaves (2.4 step 4's most), 244 bytes each way (2.2.1's most): 5 words
 * for the first two slaves, 4 for the others. */
static md810_gateway_node_config_t bridge_at_the_limits(void)
{
    uint8_t words[MD810_GATEWAY_NODES];
    size_t i;
    for (i = 0U; i < MD810_GATEWAY_NODES; i++) {
        words[i] = (i < 2U) ? 5U : 4U;
    }
    return bridge_config(30U, words, sizeof words, words, sizeof words);
}

static bool bridge_same_config(const md810_gateway_node_config_t *a,
                               const md810_gateway_node_config_t *b)
{
    return (a->node_count == b->node_count) &&
           same_bytes(a->input_words, b->input_words, MD810_GATEWAY_NODES) &&
           same_bytes(a->output_words, b->output_words, MD810_GATEWAY_NODES);
}

static bool bridge_all_zero(const uint8_t *bytes, size_t len)
{
    size_t i;
    for (i = 0U; i < len; i++) {
        if (bytes[i] != 0U) {
            return false;
        }
    }
    return true;
}

/* The words the example carries (2.4 step 5), and its User_Prm_Data: the
 * count, then TPDO and RPDO words slave by slave. */
static void bridge_the_manuals_example_is_240_bytes_in_and_128_out(void)
{
    md810_gateway_node_config_t example = bridge_manual_example();
    md810_gateway_node_config_t decoded = MD810_GATEWAY_NODE_CONFIG_DEFAULT;
    md810_gateway_user_prm_t prm;
    gsdc_totals_t totals = md810_gateway_node_totals(&example);
    uint8_t user_prm[MD810_GATEWAY_USER_PRM_LEN];
    static const uint8_t start[5] = {15U, 8U, 8U, 8U, 8U};
    static const uint8_t slave_8[4] = {8U, 8U, 8U, 0U};
    static const uint8_t slave_15[2] = {8U, 0U};
    CHECK(totals.fault == GSDC_TOTALS_OK);
    CHECK(totals.input_words == 120U && totals.output_words == 64U);
    CHECK(gsdc_totals_input_len(&totals) == 240U);
    CHECK(gsdc_totals_output_len(&totals) == 128U);
    CHECK(md810_gateway_node_config_encode(&example, user_prm).fault == GSDC_PRM_OK);
    CHECK(same_bytes(user_prm, start, sizeof start));
    CHECK(same_bytes(&user_prm[15], slave_8, sizeof slave_8));
    CHECK(same_bytes(&user_prm[29], slave_15, sizeof slave_15));
    CHECK(bridge_all_zero(&user_prm[31], sizeof user_prm - 31U));
    CHECK(md810_gateway_node_config_decode(user_prm, sizeof user_prm, &decoded).fault ==
          GSDC_PRM_OK);
    CHECK(bridge_same_config(&decoded, &example));
    CHECK(md810_gateway_decode_user_prm(user_prm, sizeof user_prm, &prm).fault == GSDC_PRM_OK);
    CHECK(bridge_same_config(&prm.nodes, &example));
}

/* The master plugs modules until INPUT and OUTPUT equal the totals (2.4
 * step 5): 7 x 16 + 8 words in, 4 x 16 words out. */
static void bridge_the_example_s_modules_carry_its_totals(void)
{
    static const uint8_t plugged[12] = {
        MD810_GATEWAY_INPUT_16_WORDS_CONFIG,  MD810_GATEWAY_INPUT_16_WORDS_CONFIG,
        MD810_GATEWAY_INPUT_16_WORDS_CONFIG,  MD810_GATEWAY_INPUT_16_WORDS_CONFIG,
        MD810_GATEWAY_INPUT_16_WORDS_CONFIG,  MD810_GATEWAY_INPUT_16_WORDS_CONFIG,
        MD810_GATEWAY_INPUT_16_WORDS_CONFIG,  MD810_GATEWAY_INPUT_8_WORDS_CONFIG,
        MD810_GATEWAY_OUTPUT_16_WORDS_CONFIG, MD810_GATEWAY_OUTPUT_16_WORDS_CONFIG,
        MD810_GATEWAY_OUTPUT_16_WORDS_CONFIG, MD810_GATEWAY_OUTPUT_16_WORDS_CONFIG,
    };
    static const uint8_t unknown[2] = {0x5FU, 0xF3U};
    uint8_t too_many[21];
    md810_gateway_node_config_t example = bridge_manual_example();
    gsdc_totals_t nodes = md810_gateway_node_totals(&example);
    gsdc_totals_t modules = md810_gateway_config_totals(plugged, sizeof plugged);
    size_t i;
    CHECK(modules.fault == GSDC_TOTALS_OK);
    CHECK(modules.input_words == 120U && modules.output_words == 64U);
    CHECK(gsdc_totals_match(&nodes, &modules));
    modules = md810_gateway_config_totals(plugged, sizeof plugged - 1U);
    CHECK(modules.fault == GSDC_TOTALS_OK);
    CHECK(!gsdc_totals_match(&nodes, &modules));
    modules = md810_gateway_config_totals(unknown, sizeof unknown);
    CHECK(modules.fault == GSDC_TOTALS_UNKNOWN_MODULE);
    CHECK(modules.at == 1U && modules.byte == 0xF3U);
    CHECK(!gsdc_totals_match(&nodes, &modules));
    for (i = 0U; i < sizeof too_many; i++) {
        too_many[i] = MD810_GATEWAY_INPUT_1_WORD_CONFIG;
    }
    modules = md810_gateway_config_totals(too_many, sizeof too_many);
    CHECK(modules.fault == GSDC_TOTALS_TOO_MANY_MODULES);
    CHECK(modules.len == 21U && modules.max == MD810_GATEWAY_MAX_MODULES);
    CHECK(md810_gateway_config_totals(too_many, MD810_GATEWAY_MAX_MODULES).fault ==
          GSDC_TOTALS_OK);
}

/* The slaves' words follow each other in ascending slave number. */
static void bridge_each_slave_s_words_have_their_place(void)
{
    md810_gateway_node_config_t example = bridge_manual_example();
    size_t offset = 999U;
    CHECK(md810_gateway_input_offset(&example, 1U, &offset) && offset == 0U);
    CHECK(md810_gateway_input_offset(&example, 15U, &offset) && offset == 14U * 16U);
    CHECK(md810_gateway_output_offset(&example, 9U, &offset) && offset == 8U * 16U);
    offset = 999U;
    CHECK(!md810_gateway_input_offset(&example, 16U, &offset));
    CHECK(!md810_gateway_input_offset(&example, 0U, &offset));
    CHECK(offset == 999U);
}

static void bridge_thirty_slaves_and_244_bytes_pass(void)
{
    md810_gateway_node_config_t limits = bridge_at_the_limits();
    md810_gateway_node_config_t decoded = MD810_GATEWAY_NODE_CONFIG_DEFAULT;
    gsdc_totals_t totals = md810_gateway_node_totals(&limits);
    uint8_t user_prm[MD810_GATEWAY_USER_PRM_LEN];
    CHECK(totals.fault == GSDC_TOTALS_OK);
    CHECK(gsdc_totals_input_len(&totals) == 244U);
    CHECK(gsdc_totals_output_len(&totals) == 244U);
    CHECK(md810_gateway_node_config_encode(&limits, user_prm).fault == GSDC_PRM_OK);
    CHECK(md810_gateway_node_config_decode(user_prm, sizeof user_prm, &decoded).fault ==
          GSDC_PRM_OK);
    CHECK(bridge_same_config(&decoded, &limits));
}

/* "配置 CANopen 从站数最大为 30 个" (2.4 step 4): the totals, the encoder and
 * the decoder refuse 31, and the refusing encoder and decoder write nothing. */
static void bridge_a_31st_slave_is_refused(void)
{
    md810_gateway_node_config_t config = bridge_at_the_limits();
    md810_gateway_node_config_t decoded = MD810_GATEWAY_NODE_CONFIG_DEFAULT;
    md810_gateway_node_config_t untouched = MD810_GATEWAY_NODE_CONFIG_DEFAULT;
    uint8_t user_prm[MD810_GATEWAY_USER_PRM_LEN];
    uint8_t written[MD810_GATEWAY_USER_PRM_LEN];
    gsdc_totals_t totals;
    gsdc_prm_result_t result;
    CHECK(md810_gateway_node_config_encode(&config, user_prm).fault == GSDC_PRM_OK);
    gsdc_copy_bytes(written, user_prm, sizeof user_prm);
    config.node_count = 31U;
    totals = md810_gateway_node_totals(&config);
    CHECK(totals.fault == GSDC_TOTALS_NODE_COUNT && totals.count == 31U);
    result = md810_gateway_node_config_encode(&config, user_prm);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 0U && result.value == 31U);
    CHECK(same_bytes(user_prm, written, sizeof user_prm));
    user_prm[0] = 31U;
    result = md810_gateway_node_config_decode(user_prm, sizeof user_prm, &decoded);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 0U && result.value == 31U);
    CHECK(bridge_same_config(&decoded, &untouched));
}

/* One word more is 246 bytes: the 245th byte is one too many, either way. */
static void bridge_a_245th_byte_is_refused(void)
{
    md810_gateway_node_config_t more_in = bridge_at_the_limits();
    md810_gateway_node_config_t more_out = bridge_at_the_limits();
    gsdc_totals_t totals;
    more_in.input_words[2] = 5U;
    totals = md810_gateway_node_totals(&more_in);
    CHECK(totals.fault == GSDC_TOTALS_TOO_LONG && totals.direction == GSDC_DIRECTION_IN);
    CHECK(totals.len == 246U && totals.max == MD810_GATEWAY_MAX_INPUT_LEN);
    CHECK(totals.input_words == 0U && totals.output_words == 0U);
    more_out.output_words[29] = 5U;
    totals = md810_gateway_node_totals(&more_out);
    CHECK(totals.fault == GSDC_TOTALS_TOO_LONG && totals.direction == GSDC_DIRECTION_OUT);
    CHECK(totals.len == 246U && totals.max == MD810_GATEWAY_MAX_OUTPUT_LEN);
}

/* At most two PDOs (8 function codes) each way per slave (2.2.1), and no
 * words for a slave past the count. */
static void bridge_a_slave_s_words_keep_to_their_range(void)
{
    md810_gateway_node_config_t nine = bridge_manual_example();
    md810_gateway_node_config_t example = bridge_manual_example();
    md810_gateway_node_config_t decoded;
    md810_gateway_node_config_t past;
    static const uint8_t ones[3] = {1U, 1U, 1U};
    uint8_t user_prm[MD810_GATEWAY_USER_PRM_LEN];
    gsdc_totals_t totals;
    gsdc_prm_result_t result;
    nine.input_words[3] = 9U;
    totals = md810_gateway_node_totals(&nine);
    CHECK(totals.fault == GSDC_TOTALS_WORDS && totals.node == 4U);
    CHECK(totals.direction == GSDC_DIRECTION_IN && totals.words == 9U);
    CHECK(md810_gateway_node_config_encode(&example, user_prm).fault == GSDC_PRM_OK);
    user_prm[7] = 9U;
    result = md810_gateway_node_config_decode(user_prm, sizeof user_prm, &decoded);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 7U && result.value == 9U);
    user_prm[7] = 8U;
    user_prm[8] = 9U; /* slave 4's RPDO words */
    result = md810_gateway_node_config_decode(user_prm, sizeof user_prm, &decoded);
    CHECK(result.fault == GSDC_PRM_NOT_ALLOWED && result.offset == 8U && result.value == 9U);
    past = bridge_config(2U, ones, sizeof ones, ones, 0U);
    totals = md810_gateway_node_totals(&past);
    CHECK(totals.fault == GSDC_TOTALS_UNUSED_NODE && totals.node == 3U);
}

/* The GSD's defaults: the bridge alone, no words. */
static void bridge_the_default_is_the_bridge_alone(void)
{
    static const md810_gateway_node_config_t defaults = MD810_GATEWAY_NODE_CONFIG_DEFAULT;
    md810_gateway_node_config_t decoded;
    uint8_t user_prm[MD810_GATEWAY_USER_PRM_LEN] = {0U};
    uint8_t encoded[MD810_GATEWAY_USER_PRM_LEN];
    gsdc_totals_t totals = md810_gateway_node_totals(&defaults);
    gsdc_prm_result_t result;
    user_prm[0] = 1U;
    CHECK(md810_gateway_node_config_decode(user_prm, sizeof user_prm, &decoded).fault ==
          GSDC_PRM_OK);
    CHECK(bridge_same_config(&decoded, &defaults));
    CHECK(md810_gateway_node_config_encode(&defaults, encoded).fault == GSDC_PRM_OK);
    CHECK(same_bytes(encoded, user_prm, sizeof user_prm));
    CHECK(totals.fault == GSDC_TOTALS_OK);
    CHECK(totals.input_words == 0U && totals.output_words == 0U);
    result = md810_gateway_node_config_decode(&user_prm[1], sizeof user_prm - 1U, &decoded);
    CHECK(result.fault == GSDC_PRM_LENGTH);
    CHECK(result.expected == MD810_GATEWAY_USER_PRM_LEN);
    CHECK(result.found == MD810_GATEWAY_USER_PRM_LEN - 1U);
}

/* What the layout says, the GSD generated beside it says: lengths, modules,
 * the limits. */
static void bridge_the_layout_agrees_with_the_gsd(void)
{
    static const uint8_t gsd_modules[] = {GSD_GW_MODULE_CONFIGS};
    static const uint8_t configs[MD810_GATEWAY_MODULE_CONFIGS_COUNT] =
        MD810_GATEWAY_MODULE_CONFIGS;
    CHECK(MD810_GATEWAY_USER_PRM_LEN == GSD_GW_MAX_USER_PRM_DATA_LEN);
    CHECK(6U + MD810_GATEWAY_DIAG_MAX_LEN == GSD_GW_MAX_DIAG_DATA_LEN);
    CHECK(MD810_GATEWAY_MAX_INPUT_LEN == GSD_GW_MAX_INPUT_LEN);
    CHECK(MD810_GATEWAY_MAX_OUTPUT_LEN == GSD_GW_MAX_OUTPUT_LEN);
    CHECK(MD810_GATEWAY_MAX_MODULES == GSD_GW_MAX_MODULE);
    CHECK(sizeof gsd_modules == MD810_GATEWAY_MODULE_CONFIGS_COUNT);
    CHECK(same_bytes(configs, gsd_modules, sizeof configs));
}

/* 2.5's table, bytes 6 to 10 of SFC13's record: length, type, CANopen
 * slave, code, and a fifth byte, "保留" (reserved) unless the type is 4. */
typedef struct {
    uint8_t bytes[5];
    size_t len;
    md810_gateway_diagnosis_t diagnosis;
} bridge_diag_case_t;

static const bridge_diag_case_t bridge_diag_cases[4] = {
    /* 参数错误（1）, 参数PDO长度与变频器不匹配（35）. */
    {{4U, 1U, 7U, 35U, 0U},
     4U,
     {MD810_GATEWAY_DIAG_PARAMETER_ERROR, 7U,
      MD810_GATEWAY_DIAG_PARAMETER_ERROR_CODE_PARAMETER_PDO_LENGTH_DOES_NOT_MATCH_THE_DRIVE}},
    /* 参数错误（1）, 配置中有节点未在线（34）. */
    {{4U, 1U, 30U, 34U, 0U},
     4U,
     {MD810_GATEWAY_DIAG_PARAMETER_ERROR, 30U,
      MD810_GATEWAY_DIAG_PARAMETER_ERROR_CODE_NODE_IN_THE_CONFIGURATION_NOT_ONLINE}},
    /* CANopen 网络故障（3）, 运行中 CANopen 从站掉线（32）. */
    {{4U, 3U, 1U, 32U, 0U},
     4U,
     {MD810_GATEWAY_DIAG_CANOPEN_NETWORK_FAULT, 1U,
      MD810_GATEWAY_DIAG_CANOPEN_NETWORK_FAULT_CODE_CANOPEN_SLAVE_DROPPED_OUT_WHILE_RUNNING}},
    /* 变频报故障（4）: 变频器故障（高字节）, （低字节）. */
    {{5U, 4U, 12U, 0x23U, 0x01U}, 5U, {MD810_GATEWAY_DIAG_DRIVE_REPORTS_FAULT, 12U, 0x2301U}},
};

static bool bridge_same_diagnosis(const md810_gateway_diagnosis_t *a,
                                  const md810_gateway_diagnosis_t *b)
{
    return (a->kind == b->kind) && (a->node == b->node) && (a->code == b->code);
}

static void bridge_the_four_diagnosis_blocks_decode_and_encode_back(void)
{
    size_t i;
    CHECK(MD810_GATEWAY_DIAG_PARAMETER_ERROR == 1U);
    CHECK(MD810_GATEWAY_DIAG_CANOPEN_NETWORK_FAULT == 3U);
    CHECK(MD810_GATEWAY_DIAG_DRIVE_REPORTS_FAULT == 4U);
    for (i = 0U; i < 4U; i++) {
        const bridge_diag_case_t *c = &bridge_diag_cases[i];
        md810_gateway_diagnosis_t decoded = {0U, 0U, 0U};
        uint8_t block[MD810_GATEWAY_DIAG_MAX_LEN] = {0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU};
        size_t len = 0U;
        CHECK(md810_gateway_diagnosis_decode(c->bytes, c->len, &decoded).fault == GSDC_DIAG_OK);
        CHECK(bridge_same_diagnosis(&decoded, &c->diagnosis));
        CHECK(md810_gateway_diagnosis_encode(&c->diagnosis, block, &len).fault == GSDC_DIAG_OK);
        CHECK(len == c->len);
        CHECK(same_bytes(block, c->bytes, c->len));
    }
}

/* SFC13 reads bytes 6 to 10 whatever the length: the reserved fifth byte of
 * a 4-byte block is past its length and not read. */
static void bridge_the_reserved_byte_is_not_read(void)
{
    static const uint8_t record[5] = {4U, 3U, 1U, 32U, 0xAAU};
    md810_gateway_diagnosis_t decoded = {0U, 0U, 0U};
    CHECK(md810_gateway_diagnosis_decode(record, sizeof record, &decoded).fault == GSDC_DIAG_OK);
    CHECK(bridge_same_diagnosis(&decoded, &bridge_diag_cases[2].diagnosis));
}

/* A block the table does not have, and why it is refused. */
typedef struct {
    uint8_t bytes[5];
    size_t len;
    gsdc_diag_fault_t fault;
    /* GSDC_DIAG_SHORT and GSDC_DIAG_LENGTH: expected and found; the others:
     * the type (of a code) and the value. */
    size_t a;
    size_t b;
} bridge_refused_t;

static void bridge_blocks_the_table_does_not_have_are_refused(void)
{
    static const bridge_refused_t refused[10] = {
        {{4U, 2U, 7U, 35U, 0U}, 4U, GSDC_DIAG_TYPE, 0U, 2U},
        {{4U, 1U, 31U, 35U, 0U}, 4U, GSDC_DIAG_NODE, 0U, 31U},
        {{4U, 1U, 0U, 35U, 0U}, 4U, GSDC_DIAG_NODE, 0U, 0U},
        {{4U, 1U, 7U, 33U, 0U}, 4U, GSDC_DIAG_CODE, 1U, 33U},
        {{4U, 3U, 7U, 34U, 0U}, 4U, GSDC_DIAG_CODE, 3U, 34U},
        {{5U, 1U, 7U, 35U, 0U}, 5U, GSDC_DIAG_LENGTH, 4U, 5U},
        {{4U, 4U, 7U, 0x23U, 0U}, 4U, GSDC_DIAG_LENGTH, 5U, 4U},
        {{5U, 4U, 7U, 0x23U, 0U}, 4U, GSDC_DIAG_SHORT, 5U, 4U},
        {{0x44U, 1U, 7U, 35U, 0U}, 4U, GSDC_DIAG_HEADER, 0U, 0x44U},
        {{0U, 0U, 0U, 0U, 0U}, 0U, GSDC_DIAG_SHORT, 1U, 0U},
    };
    static const md810_gateway_diagnosis_t untouched = {0xEEU, 0xEEU, 0xEEEEU};
    size_t i;
    for (i = 0U; i < 10U; i++) {
        const bridge_refused_t *r = &refused[i];
        md810_gateway_diagnosis_t decoded = untouched;
        gsdc_diag_result_t result = md810_gateway_diagnosis_decode(r->bytes, r->len, &decoded);
        bool lengths = (r->fault == GSDC_DIAG_SHORT) || (r->fault == GSDC_DIAG_LENGTH);
        CHECK(result.fault == r->fault);
        if (lengths) {
            CHECK(result.expected == r->a && result.found == r->b);
        } else {
            CHECK(result.kind == r->a && result.value == r->b);
        }
        CHECK(bridge_same_diagnosis(&decoded, &untouched));
    }
}

/* What C adds: the struct holds any numbers, so the encoder refuses a type,
 * a node or a code the table does not have, and writes nothing then. */
static void bridge_diagnoses_the_table_does_not_have_are_not_encoded(void)
{
    static const md810_gateway_diagnosis_t refused[5] = {
        {2U, 7U, 35U},
        {MD810_GATEWAY_DIAG_PARAMETER_ERROR, 31U, 35U},
        {MD810_GATEWAY_DIAG_PARAMETER_ERROR, 7U, 33U},
        {MD810_GATEWAY_DIAG_CANOPEN_NETWORK_FAULT, 7U, 32U + 0x100U},
        {MD810_GATEWAY_DIAG_DRIVE_REPORTS_FAULT, 0U, 0x2301U},
    };
    static const gsdc_diag_fault_t faults[5] = {GSDC_DIAG_TYPE, GSDC_DIAG_NODE, GSDC_DIAG_CODE,
                                                GSDC_DIAG_CODE, GSDC_DIAG_NODE};
    static const uint8_t untouched[MD810_GATEWAY_DIAG_MAX_LEN] = {0xEEU, 0xEEU, 0xEEU, 0xEEU,
                                                                  0xEEU};
    size_t i;
    for (i = 0U; i < 5U; i++) {
        uint8_t block[MD810_GATEWAY_DIAG_MAX_LEN] = {0xEEU, 0xEEU, 0xEEU, 0xEEU, 0xEEU};
        size_t len = 99U;
        CHECK(md810_gateway_diagnosis_encode(&refused[i], block, &len).fault == faults[i]);
        CHECK(same_bytes(block, untouched, sizeof block));
        CHECK(len == 99U);
    }
}

/* ------------------------------------------------------------------------
 * PROFIdrive (the fixture): PPO1 carries the profile's parameter channel;
 * its parameters are numbered group * 100 + index. */

/* P10.05, the setting's parameter: PNU 1005. */
#define P10_05 1005U

/* A PPO1 telegram of the fixture carrying `pkw` and the PZD words 047F 4000. */
static void pd_ppo1(const char *pkw, uint8_t telegram[PROFIDRIVE_PPO1_BYTES])
{
    uint8_t pzd[4];
    words(pkw, telegram, GSDC_PKW_BYTES);
    words("047F 4000", pzd, sizeof pzd);
    gsdc_copy_bytes(&telegram[PROFIDRIVE_PPO1_PZD_OFFSET], pzd, sizeof pzd);
}

/* The master reads P10.05 (request 1, PKE 13ED); the drive answers the
 * word 1 (response 1, PWE2). */
static void profidrive_read_p10_05(void)
{
    profidrive_ppo1_out_t out;
    profidrive_ppo1_in_t answer;
    uint8_t again[GSDC_PKW_BYTES] = {0};
    gsdc_profidrive_request_t request;
    gsdc_profidrive_response_t response;
    CHECK(PROFIDRIVE_SETTINGS_1_PARAMETER == P10_05);
    pd_ppo1("13ED 0000 0000 0000", out.bytes);
    CHECK(gsdc_profidrive_request_decode(out.bytes, &request) == GSDC_PKW_OK);
    CHECK(request.id == GSDC_PROFIDRIVE_READ);
    CHECK(request.pnu == P10_05);
    CHECK(request.subindex == 0U);
    CHECK(request.value == 0U);
    CHECK(gsdc_word_get(&out.bytes[PROFIDRIVE_PPO1_PZD_OFFSET], 0U) == 0x047FU);
    CHECK(gsdc_profidrive_request_encode(&request, again) == GSDC_PKW_OK);
    CHECK(same_bytes(again, out.bytes, GSDC_PKW_BYTES));
    pd_ppo1("13ED 0000 0000 0001", answer.bytes);
    CHECK(gsdc_profidrive_response_decode(answer.bytes, &response) == GSDC_PKW_OK);
    CHECK(response.id == GSDC_PROFIDRIVE_VALUE_WORD);
    CHECK(response.pnu == P10_05);
    CHECK(response.value == 1U);
    CHECK(gsdc_profidrive_response_encode(&response, again) == GSDC_PKW_OK);
    CHECK(same_bytes(again, answer.bytes, GSDC_PKW_BYTES));
}

/* The master writes the word 1 to P10.05 (request 2), and a double word to
 * element 3 of it (request 8: PWE1 high word, PWE2 low word, IND 0300). */
static void profidrive_write_a_word_to_p10_05(void)
{
    profidrive_ppo1_out_t out;
    profidrive_ppo1_out_t sent;
    gsdc_profidrive_request_t write;
    gsdc_profidrive_request_t decoded;
    write.id = GSDC_PROFIDRIVE_WRITE_WORD;
    write.pnu = P10_05;
    write.subindex = 0U;
    write.value = 1U;
    pd_ppo1("23ED 0000 0000 0001", out.bytes);
    CHECK(gsdc_profidrive_request_decode(out.bytes, &decoded) == GSDC_PKW_OK);
    CHECK(decoded.id == write.id);
    CHECK(decoded.pnu == write.pnu);
    CHECK(decoded.value == write.value);
    sent = out;
    words("FFFF FFFF FFFF FFFF", sent.bytes, GSDC_PKW_BYTES);
    CHECK(gsdc_profidrive_request_encode(&write, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, out.bytes, PROFIDRIVE_PPO1_BYTES));
    write.id = GSDC_PROFIDRIVE_WRITE_ARRAY_DOUBLE_WORD;
    write.subindex = 3U;
    write.value = 100000U;
    pd_ppo1("83ED 0300 0001 86A0", out.bytes);
    CHECK(gsdc_profidrive_request_encode(&write, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, out.bytes, PROFIDRIVE_PPO1_BYTES));
    CHECK(gsdc_profidrive_request_decode(out.bytes, &decoded) == GSDC_PKW_OK);
    CHECK(decoded.subindex == 3U);
    CHECK(decoded.value == 100000U);
}

/* The drive cannot execute: response 7 with error number 2 (limit
 * exceeded) in PWE2. */
static void profidrive_error_answer(void)
{
    profidrive_ppo1_in_t answer;
    profidrive_ppo1_in_t sent;
    gsdc_profidrive_response_t failed;
    gsdc_profidrive_response_t decoded;
    failed.id = GSDC_PROFIDRIVE_CANNOT_EXECUTE;
    failed.pnu = P10_05;
    failed.subindex = 0U;
    failed.value = GSDC_PROFIDRIVE_ERROR_LIMIT_EXCEEDED;
    pd_ppo1("73ED 0000 0000 0002", answer.bytes);
    CHECK(gsdc_profidrive_response_decode(answer.bytes, &decoded) == GSDC_PKW_OK);
    CHECK(decoded.id == failed.id);
    CHECK(decoded.pnu == failed.pnu);
    CHECK(decoded.value == 2U);
    sent = answer;
    CHECK(gsdc_profidrive_response_encode(&failed, sent.bytes) == GSDC_PKW_OK);
    CHECK(same_bytes(sent.bytes, answer.bytes, PROFIDRIVE_PPO1_BYTES));
}

/* Request 14 (Siemens' "change and store in EEPROM") is not the profile's:
 * refused both ways, with the parameter the drive answers about; an encoder
 * that refuses writes nothing. */
static void profidrive_an_illegal_id_is_refused(void)
{
    uint8_t telegram[PROFIDRIVE_PPO1_BYTES];
    uint8_t untouched[GSDC_PKW_BYTES] = {1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U};
    uint8_t pkw[GSDC_PKW_BYTES] = {1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U};
    gsdc_profidrive_request_t request;
    gsdc_profidrive_response_t response;
    pd_ppo1("E3ED 0000 0000 0001", telegram);
    CHECK(gsdc_profidrive_request_decode(telegram, &request) == GSDC_PKW_BAD_COMMAND);
    CHECK(request.id == 14U);
    CHECK(request.pnu == P10_05);
    CHECK(gsdc_profidrive_request_encode(&request, pkw) == GSDC_PKW_BAD_COMMAND);
    pd_ppo1("93ED 0000 0000 0001", telegram);
    CHECK(gsdc_profidrive_response_decode(telegram, &response) == GSDC_PKW_CHANGE_REPORT);
    CHECK(gsdc_profidrive_response_encode(&response, pkw) == GSDC_PKW_BAD_RESPONSE);
    CHECK(same_bytes(pkw, untouched, GSDC_PKW_BYTES));
}

/* Standard telegram 1 where the fixture's GSDML places it: its submodules
 * in PROFIdrive's API (0x3A00), the module access point in subslot 1 with
 * ident number 0xFFFF, the telegram in subslot 2. */
static void profidrive_standard_telegram_1_is_placed_as_the_gsdml_declares_it(void)
{
    CHECK(PROFIDRIVE_TELEGRAM1_API == 14848UL);
    CHECK(PROFIDRIVE_TELEGRAM1_ACCESS_POINT_SUBSLOT == 1U);
    CHECK(PROFIDRIVE_TELEGRAM1_ACCESS_POINT_IDENT == 0xFFFFUL);
    CHECK(PROFIDRIVE_TELEGRAM1_DATA_SUBSLOT == 2U);
    CHECK(PROFIDRIVE_TELEGRAM1_IDENT == 0x10UL);
}

/* Standard telegram 2 as ABB's FENA declares it: STW1, NSOLL_B (an
 * Unsigned32, which PROFINET sends high byte first), STW2; 8 bytes, placed
 * as telegram 1 is. NSOLL_B = 100000 (0x000186A0) is words 1 and 2. */
static void profidrive_standard_telegram_2_carries_a_32_bit_speed(void)
{
    uint8_t telegram[PROFIDRIVE_TELEGRAM2_BYTES];
    uint8_t again[PROFIDRIVE_TELEGRAM2_BYTES] = {0};
    CHECK(PROFIDRIVE_TELEGRAM2_BYTES == 8U);
    CHECK(PROFIDRIVE_TELEGRAM2_PZD_WORDS == 4U);
    CHECK(PROFIDRIVE_TELEGRAM2_IDENT == 0x20UL);
    CHECK(PROFIDRIVE_TELEGRAM2_API == 14848UL);
    CHECK(PROFIDRIVE_TELEGRAM2_DATA_SUBSLOT == 2U);
    words("047F 0001 86A0 F000", telegram, sizeof telegram);
    CHECK(gsdc_word_get(&telegram[PROFIDRIVE_TELEGRAM2_PZD_OFFSET], 0U) == 0x047FU);
    CHECK(gsdc_double_word_get(&telegram[PROFIDRIVE_TELEGRAM2_PZD_OFFSET], 1U) == 100000UL);
    CHECK(gsdc_word_get(&telegram[PROFIDRIVE_TELEGRAM2_PZD_OFFSET], 3U) == 0xF000U);
    gsdc_word_put(&again[PROFIDRIVE_TELEGRAM2_PZD_OFFSET], 0U, 0x047FU);
    gsdc_double_word_put(&again[PROFIDRIVE_TELEGRAM2_PZD_OFFSET], 1U, 100000UL);
    gsdc_word_put(&again[PROFIDRIVE_TELEGRAM2_PZD_OFFSET], 3U, 0xF000U);
    CHECK(same_bytes(again, telegram, sizeof telegram));
}

/* ------------------------------------------------------------------------ */

static const test_t tests[] = {
    {"md810_read_f0_08", md810_read_f0_08},
    {"md810_answer_50_hz", md810_answer_50_hz},
    {"md810_write_20_hz", md810_write_20_hz},
    {"md810_error_answers", md810_error_answers},
    {"md810_illegal_telegrams_are_refused", md810_illegal_telegrams_are_refused},
    {"md810_ppo5_is_32_bytes", md810_ppo5_is_32_bytes},
    {"md810_ppo_config_bytes", md810_ppo_config_bytes},
    {"md810_default_user_prm_is_f0_00_everywhere", md810_default_user_prm_is_f0_00_everywhere},
    {"md810_user_prm_maps_dpv1_indexes", md810_user_prm_maps_dpv1_indexes},
    {"md810_card_lost_the_drive_diagnosis", md810_card_lost_the_drive_diagnosis},
    {"md810_dpv1_indexes_as_a_profinet_record", md810_dpv1_indexes_as_a_profinet_record},
    {"mv810_read_p43_02", mv810_read_p43_02},
    {"mv810_write_p43_02", mv810_write_p43_02},
    {"mv810_error_reply", mv810_error_reply},
    {"mv810_control_and_status_words", mv810_control_and_status_words},
    {"mv810_standard_telegram_1_is_two_words", mv810_standard_telegram_1_is_two_words},
    {"mv810_mappings_set_at_the_drive", mv810_mappings_set_at_the_drive},
    {"every_example_of_the_manuals_round_trips", every_example_of_the_manuals_round_trips},
    {"pi9000_command_word_in_ppo3", pi9000_command_word_in_ppo3},
    {"pi9000_fault_code_diagnosis", pi9000_fault_code_diagnosis},
    {"pi9000_default_user_prm", pi9000_default_user_prm},
    {"bridge_the_manuals_example_is_240_bytes_in_and_128_out",
     bridge_the_manuals_example_is_240_bytes_in_and_128_out},
    {"bridge_the_example_s_modules_carry_its_totals",
     bridge_the_example_s_modules_carry_its_totals},
    {"bridge_each_slave_s_words_have_their_place", bridge_each_slave_s_words_have_their_place},
    {"bridge_thirty_slaves_and_244_bytes_pass", bridge_thirty_slaves_and_244_bytes_pass},
    {"bridge_a_31st_slave_is_refused", bridge_a_31st_slave_is_refused},
    {"bridge_a_245th_byte_is_refused", bridge_a_245th_byte_is_refused},
    {"bridge_a_slave_s_words_keep_to_their_range", bridge_a_slave_s_words_keep_to_their_range},
    {"bridge_the_default_is_the_bridge_alone", bridge_the_default_is_the_bridge_alone},
    {"bridge_the_layout_agrees_with_the_gsd", bridge_the_layout_agrees_with_the_gsd},
    {"bridge_the_four_diagnosis_blocks_decode_and_encode_back",
     bridge_the_four_diagnosis_blocks_decode_and_encode_back},
    {"bridge_the_reserved_byte_is_not_read", bridge_the_reserved_byte_is_not_read},
    {"bridge_blocks_the_table_does_not_have_are_refused",
     bridge_blocks_the_table_does_not_have_are_refused},
    {"bridge_diagnoses_the_table_does_not_have_are_not_encoded",
     bridge_diagnoses_the_table_does_not_have_are_not_encoded},
    {"profidrive_read_p10_05", profidrive_read_p10_05},
    {"profidrive_write_a_word_to_p10_05", profidrive_write_a_word_to_p10_05},
    {"profidrive_error_answer", profidrive_error_answer},
    {"profidrive_an_illegal_id_is_refused", profidrive_an_illegal_id_is_refused},
    {"profidrive_standard_telegram_1_is_placed_as_the_gsdml_declares_it",
     profidrive_standard_telegram_1_is_placed_as_the_gsdml_declares_it},
    {"profidrive_standard_telegram_2_carries_a_32_bit_speed",
     profidrive_standard_telegram_2_carries_a_32_bit_speed},
};

int main(void)
{
    return run_tests(tests, sizeof tests / sizeof tests[0]);
}
