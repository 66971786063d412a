/* The support code of gsdc's C firmware layouts (gsdc templates/c/gsdc_support.h).
 * Every <stem>_layout.h includes it; its guard keeps it to one copy per
 * translation unit, whatever the number of layouts included.
 *
 * C99, or C++ through extern "C"; only <stdbool.h>, <stddef.h> and
 * <stdint.h>; no allocation. Bus data stays in byte arrays and every
 * multi-byte value is read and written byte by byte, big-endian, so neither
 * the host's byte order nor the compiler's struct layout matters. Integer
 * arithmetic is unsigned and every narrowing is an explicit cast. Pointer
 * arguments must not be NULL; arrays must have the length a function names.
 */
#ifndef GSDC_SUPPORT_H
#define GSDC_SUPPORT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The gsdc release that wrote this file, as major * 10000 + minor * 100 +
 * patch: each layout refuses to compile with the support of another. */
#define GSDC_SUPPORT_VERSION 0

#ifdef __cplusplus
extern "C" {
#endif

/* GSDC_STATIC_ASSERT(condition, name): the translation unit does not compile
 * when the constant `condition` is false. C11 and C++11 check it with their
 * own assertion, C99 with an array of -1 elements, the type `name`. */
#if defined(__cplusplus) && (__cplusplus >= 201103L)
#define GSDC_STATIC_ASSERT(condition, name) static_assert((condition), #name)
#elif defined(__STDC_VERSION__) && (__STDC_VERSION__ >= 201112L)
#define GSDC_STATIC_ASSERT(condition, name) _Static_assert((condition), #name)
#else
#define GSDC_STATIC_ASSERT(condition, name) typedef char name[(condition) ? 1 : -1]
#endif

/* ------------------------------------------------------------------------
 * Words */

/* The Unsigned16 in `bytes[0]` (high byte) and `bytes[1]` (low byte). */
static inline uint16_t gsdc_u16be_get(const uint8_t bytes[2])
{
    return (uint16_t)(((uint32_t)bytes[0] << 8U) | (uint32_t)bytes[1]);
}

/* Writes `value` to `bytes[0]` (high byte) and `bytes[1]` (low byte). */
static inline void gsdc_u16be_put(uint8_t bytes[2], uint16_t value)
{
    bytes[0] = (uint8_t)((uint32_t)value >> 8U);
    bytes[1] = (uint8_t)((uint32_t)value & 0xFFU);
}

/* Word `index` (0 = the first) of the big-endian words from `words` on:
 * with a layout's <MODULE>_PZD_OFFSET, `gsdc_word_get(&telegram[offset], 0U)`
 * is PZD1. The caller keeps `index` below the number of words. */
static inline uint16_t gsdc_word_get(const uint8_t *words, size_t index)
{
    return gsdc_u16be_get(&words[2U * index]);
}

/* Writes `value` to word `index` (0 = the first) from `words` on. The caller
 * keeps `index` below the number of words. */
static inline void gsdc_word_put(uint8_t *words, size_t index, uint16_t value)
{
    gsdc_u16be_put(&words[2U * index], value);
}

/* Words `index` and `index + 1` as one 32-bit value, high word first, as
 * PROFINET sends an Unsigned32: standard telegram 2's NSOLL_B and NIST_B are
 * at index 1. The caller keeps `index + 1` below the number of words. */
static inline uint32_t gsdc_double_word_get(const uint8_t *words, size_t index)
{
    return ((uint32_t)gsdc_word_get(words, index) << 16U) |
           (uint32_t)gsdc_word_get(words, index + 1U);
}

/* Writes `value` to words `index` and `index + 1`, high word first. */
static inline void gsdc_double_word_put(uint8_t *words, size_t index, uint32_t value)
{
    gsdc_word_put(words, index, (uint16_t)(value >> 16U));
    gsdc_word_put(words, index + 1U, (uint16_t)(value & 0xFFFFU));
}

/* The field of `word` under `mask`, shifted down by `shift` (its first bit,
 * below 16): a layout's <FIELD>_MASK and <FIELD>_SHIFT. */
static inline uint16_t gsdc_field_get(uint16_t word, uint16_t mask, unsigned int shift)
{
    return (uint16_t)(((uint32_t)word & (uint32_t)mask) >> (shift & 15U));
}

/* `word` with the field under `mask` (first bit `shift`, below 16) set to
 * `value`; bits of `value` that do not fit the field are dropped. */
static inline uint16_t gsdc_field_with(uint16_t word, uint16_t mask, unsigned int shift,
                                       uint16_t value)
{
    uint32_t field = ((uint32_t)value << (shift & 15U)) & (uint32_t)mask;
    return (uint16_t)(((uint32_t)word & ~(uint32_t)mask) | field);
}

/* Copies `count` bytes from `from` to `to`. */
static inline void gsdc_copy_bytes(uint8_t *to, const uint8_t *from, size_t count)
{
    size_t i;
    for (i = 0U; i < count; i++) {
        to[i] = from[i];
    }
}

/* ------------------------------------------------------------------------
 * Parameter telegram (User_Prm_Data) and records */

/* Why a parameter telegram or record was refused. */
typedef enum {
    GSDC_PRM_OK = 0,
    /* It is `found` bytes long; it must be `expected`. */
    GSDC_PRM_LENGTH,
    /* The value at byte `offset` is `value`, which its parameter does not
     * allow (up to 32 bits: a record value of the access point or a port). */
    GSDC_PRM_NOT_ALLOWED
} gsdc_prm_fault_t;

/* What decoding a parameter telegram or record found: the fault, and the
 * fields that fault names (the others are 0). */
typedef struct {
    gsdc_prm_fault_t fault;
    size_t expected;
    size_t found;
    size_t offset;
    uint32_t value;
} gsdc_prm_result_t;

/* Whether entry `index` (0 = the first) of a group of mappings may hold
 * `value`: a layout's <group>_entry_allows. */
typedef bool (*gsdc_entry_allows_t)(size_t index, uint16_t value);

/* The bytes entry `index` of a group of mappings takes in User_Prm_Data and
 * the records: 2 (Unsigned16: every mapping), or 1 for a setting of a byte
 * (Unsigned8, or Integer8 from 0 to 127). A layout's <group>_entry_bytes. */
typedef size_t (*gsdc_entry_bytes_t)(size_t index);

/* The value of an entry of `size` bytes (1 or 2) at `bytes`, high byte
 * first. */
static inline uint16_t gsdc_entry_get(const uint8_t *bytes, size_t size)
{
    uint16_t value;
    if (size == 1U) {
        value = (uint16_t)bytes[0];
    } else {
        value = gsdc_u16be_get(bytes);
    }
    return value;
}

/* GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_prm_ok(void)
{
    gsdc_prm_result_t result;
    result.fault = GSDC_PRM_OK;
    result.expected = 0U;
    result.found = 0U;
    result.offset = 0U;
    result.value = 0U;
    return result;
}

/* GSDC_PRM_OK when `len` is `expected`, else GSDC_PRM_LENGTH. */
static inline gsdc_prm_result_t gsdc_prm_check_len(size_t len, size_t expected)
{
    gsdc_prm_result_t result = gsdc_prm_ok();
    if (len != expected) {
        result.fault = GSDC_PRM_LENGTH;
        result.expected = expected;
        result.found = len;
    }
    return result;
}

/* Checks the values of the first `count` entries, each of its
 * `entry_bytes`, from byte `offset` of `bytes` (`len` bytes long) with no
 * gaps, each with `allows`: GSDC_PRM_LENGTH when they do not fit in `len`
 * bytes, GSDC_PRM_NOT_ALLOWED for the first value `allows` refuses, else
 * GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_prm_check_values(const uint8_t *bytes, size_t len,
                                                      size_t offset, size_t count,
                                                      gsdc_entry_allows_t allows,
                                                      gsdc_entry_bytes_t entry_bytes)
{
    gsdc_prm_result_t result = gsdc_prm_ok();
    size_t need = 0U;
    size_t at = offset;
    size_t i;
    for (i = 0U; i < count; i++) {
        need += entry_bytes(i);
    }
    if ((offset > len) || (need > (len - offset))) {
        result.fault = GSDC_PRM_LENGTH;
        result.expected = offset + need;
        result.found = len;
    }
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < count); i++) {
        uint16_t value = gsdc_entry_get(&bytes[at], entry_bytes(i));
        if (!allows(i, value)) {
            result.fault = GSDC_PRM_NOT_ALLOWED;
            result.offset = at;
            result.value = value;
        }
        at += entry_bytes(i);
    }
    return result;
}

/* Copies the values of the first `count` entries, each of its
 * `entry_bytes`, from byte `offset` of `bytes` into `values`;
 * gsdc_prm_check_values has found them there. */
static inline void gsdc_prm_get_values(const uint8_t *bytes, size_t offset, size_t count,
                                       gsdc_entry_bytes_t entry_bytes, uint16_t *values)
{
    size_t at = offset;
    size_t i;
    for (i = 0U; i < count; i++) {
        values[i] = gsdc_entry_get(&bytes[at], entry_bytes(i));
        at += entry_bytes(i);
    }
}

/* gsdc_prm_check_values, then, when the result is GSDC_PRM_OK,
 * gsdc_prm_get_values: `values` is written only then. */
static inline gsdc_prm_result_t gsdc_prm_read_values(const uint8_t *bytes, size_t len,
                                                     size_t offset, size_t count,
                                                     gsdc_entry_allows_t allows,
                                                     gsdc_entry_bytes_t entry_bytes,
                                                     uint16_t *values)
{
    gsdc_prm_result_t result =
        gsdc_prm_check_values(bytes, len, offset, count, allows, entry_bytes);
    if (result.fault == GSDC_PRM_OK) {
        gsdc_prm_get_values(bytes, offset, count, entry_bytes, values);
    }
    return result;
}

/* The value a PROFINET module fixes for a setting: the module with this
 * ident number writes it; the user cannot change it. */
typedef struct {
    uint32_t module_ident;
    uint16_t value;
} gsdc_module_value_t;

/* GSDC_PRM_OK when `len` is even and at most `max`: a record that holds the
 * first values of a group (a module's PZD record holds the words it
 * transports); else GSDC_PRM_LENGTH. */
static inline gsdc_prm_result_t gsdc_prm_check_prefix_len(size_t len, size_t max)
{
    gsdc_prm_result_t result = gsdc_prm_ok();
    if (((len % 2U) != 0U) || (len > max)) {
        result.fault = GSDC_PRM_LENGTH;
        result.expected = max;
        result.found = len;
    }
    return result;
}

/* ------------------------------------------------------------------------
 * Device-related diagnosis */

/* Bits `first` to `last` (at most 16 bits) of a device-related diagnosis
 * block, `len` bytes with the header byte first, numbered as the GSD's
 * Unit_Diag_Area numbers them: bit 0 is the lowest bit of the byte after the
 * header, bit 8 the lowest of the next byte. The value has the area's first
 * bit lowest; bits beyond the block read 0. */
static inline uint16_t gsdc_diag_area_get(const uint8_t *block, size_t len, unsigned int first,
                                          unsigned int last)
{
    uint32_t value = 0U;
    unsigned int i;
    for (i = 0U; (first <= last) && (i <= (last - first)) && (i < 16U); i++) {
        unsigned int bit = first + i;
        size_t at = 1U + (size_t)(bit / 8U);
        if ((at < len) && ((((uint32_t)block[at] >> (bit % 8U)) & 1U) != 0U)) {
            value |= (uint32_t)1U << i;
        }
    }
    return (uint16_t)value;
}

/* Sets bits `first` to `last` (at most 16 bits) of the block to `value`,
 * numbered as gsdc_diag_area_get reads them; bits of `value` that do not fit
 * the area, and bits beyond the block, are dropped. */
static inline void gsdc_diag_area_set(uint8_t *block, size_t len, unsigned int first,
                                      unsigned int last, uint16_t value)
{
    unsigned int i;
    for (i = 0U; (first <= last) && (i <= (last - first)) && (i < 16U); i++) {
        unsigned int bit = first + i;
        size_t at = 1U + (size_t)(bit / 8U);
        uint32_t mask = (uint32_t)1U << (bit % 8U);
        if (at < len) {
            if ((((uint32_t)value >> i) & 1U) != 0U) {
                block[at] = (uint8_t)((uint32_t)block[at] | mask);
            } else {
                block[at] = (uint8_t)((uint32_t)block[at] & ~mask);
            }
        }
    }
}

/* ------------------------------------------------------------------------
 * The PKW channel: 8 bytes at the start of a telegram that has one */

#define GSDC_PKW_BYTES 8U

/* What a PKW decoder or encoder says of a telegram: GSDC_PKW_OK for one the
 * manual defines, else the first thing it does not. */
typedef enum {
    GSDC_PKW_OK = 0,
    /* A request command the manual (or the PROFIdrive profile) does not define. */
    GSDC_PKW_BAD_COMMAND,
    /* A response code the manual (or the profile) does not define (PKE, IND,
     * PWE; PROFIdrive). */
    GSDC_PKW_BAD_RESPONSE,
    /* "Cannot execute" with an error code other than 1 to 4 (PKE, IND, PWE). */
    GSDC_PKW_BAD_ERROR_CODE,
    /* A read whose count is not 1 (station, command, address, value). */
    GSDC_PKW_BAD_READ_COUNT,
    /* A parameter number beyond GSDC_PROFIDRIVE_PNU_MAX (PROFIdrive). */
    GSDC_PKW_BAD_PNU,
    /* A value beyond 0xFFFF for an id that carries a word (PROFIdrive). */
    GSDC_PKW_BAD_VALUE,
    /* A parameter change report, response 9 to 12, which the PROFIdrive
     * codec does not carry. */
    GSDC_PKW_CHANGE_REPORT
} gsdc_pkw_status_t;

/* The PKW channel, PROFIdrive style (MD810): PKE, IND, PWE high, PWE low.
 * PKE bits 15-12 hold the command or response code, PKE bits 7-0 the
 * parameter address's high byte, IND bits 15-8 its low byte, the PWE low
 * word the value or error code. Reserved bits (PKE 11-8, IND 7-0, the PWE
 * high word) are written 0 and not read, and neither is the rest of a
 * telegram without a request: a master may leave old values there. */

/* Request commands and response codes: PKE bits 15-12. */
#define GSDC_PKE_NO_REQUEST 0U
#define GSDC_PKE_READ 1U
#define GSDC_PKE_WRITE 2U
#define GSDC_PKE_DONE 1U
#define GSDC_PKE_CANNOT_EXECUTE 7U

/* Why a request cannot be executed: the PWE low word of response 7. */
#define GSDC_PKE_ERROR_ILLEGAL_COMMAND 1U
#define GSDC_PKE_ERROR_ILLEGAL_ADDRESS 2U
#define GSDC_PKE_ERROR_ILLEGAL_DATA 3U
#define GSDC_PKE_ERROR_OTHER 4U

/* A parameter request from the master. */
typedef struct {
    /* GSDC_PKE_NO_REQUEST, GSDC_PKE_READ or GSDC_PKE_WRITE. */
    uint8_t command;
    /* The parameter's address; 0 without a request. */
    uint16_t address;
    /* The value a write writes; 0 for the others. */
    uint16_t value;
} gsdc_pke_request_t;

/* The drive's answer to a parameter request. */
typedef struct {
    /* GSDC_PKE_NO_REQUEST, GSDC_PKE_DONE or GSDC_PKE_CANNOT_EXECUTE. */
    uint8_t code;
    /* The parameter's address; 0 without a request. */
    uint16_t address;
    /* Done: the parameter's value, after a write the value written.
     * Cannot execute: the error code, GSDC_PKE_ERROR_ILLEGAL_COMMAND to
     * GSDC_PKE_ERROR_OTHER. 0 without a request. */
    uint16_t value;
} gsdc_pke_response_t;

/* Writes PKE, IND, PWE high and PWE low of a code, an address and a value. */
static inline void gsdc_pke_words(uint8_t pkw[GSDC_PKW_BYTES], unsigned int code,
                                  uint16_t address, uint16_t value)
{
    pkw[0] = (uint8_t)((code & 0x0FU) << 4U);
    pkw[1] = (uint8_t)((uint32_t)address >> 8U);
    pkw[2] = (uint8_t)((uint32_t)address & 0xFFU);
    pkw[3] = 0U;
    pkw[4] = 0U;
    pkw[5] = 0U;
    gsdc_u16be_put(&pkw[6], value);
}

/* The code of PKE bits 15-12. */
static inline uint8_t gsdc_pke_code(const uint8_t pkw[GSDC_PKW_BYTES])
{
    return (uint8_t)((uint32_t)pkw[0] >> 4U);
}

/* The address of PKE bits 7-0 and IND bits 15-8. */
static inline uint16_t gsdc_pke_address(const uint8_t pkw[GSDC_PKW_BYTES])
{
    return (uint16_t)(((uint32_t)pkw[1] << 8U) | (uint32_t)pkw[2]);
}

/* Decodes the master's request in `pkw`. GSDC_PKW_OK: `request` holds it.
 * GSDC_PKW_BAD_COMMAND, for a command other than 0, 1 and 2: `request`
 * holds that command and its address, which the drive answers with
 * GSDC_PKE_CANNOT_EXECUTE and GSDC_PKE_ERROR_ILLEGAL_COMMAND. */
static inline gsdc_pkw_status_t gsdc_pke_request_decode(const uint8_t pkw[GSDC_PKW_BYTES],
                                                        gsdc_pke_request_t *request)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    request->command = gsdc_pke_code(pkw);
    request->address = gsdc_pke_address(pkw);
    request->value = 0U;
    switch (request->command) {
    case GSDC_PKE_NO_REQUEST:
        request->address = 0U;
        break;
    case GSDC_PKE_READ:
        break;
    case GSDC_PKE_WRITE:
        request->value = gsdc_u16be_get(&pkw[6]);
        break;
    default:
        status = GSDC_PKW_BAD_COMMAND;
        break;
    }
    return status;
}

/* Encodes `request` into `pkw`: GSDC_PKW_OK. A read's value and a
 * no-request's address and value are written 0. GSDC_PKW_BAD_COMMAND, and
 * `pkw` untouched, for a command other than 0, 1 and 2. */
static inline gsdc_pkw_status_t gsdc_pke_request_encode(const gsdc_pke_request_t *request,
                                                        uint8_t pkw[GSDC_PKW_BYTES])
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    switch (request->command) {
    case GSDC_PKE_NO_REQUEST:
        gsdc_pke_words(pkw, GSDC_PKE_NO_REQUEST, 0U, 0U);
        break;
    case GSDC_PKE_READ:
        gsdc_pke_words(pkw, GSDC_PKE_READ, request->address, 0U);
        break;
    case GSDC_PKE_WRITE:
        gsdc_pke_words(pkw, GSDC_PKE_WRITE, request->address, request->value);
        break;
    default:
        status = GSDC_PKW_BAD_COMMAND;
        break;
    }
    return status;
}

/* Decodes the drive's response in `pkw`. GSDC_PKW_OK: `response` holds it.
 * GSDC_PKW_BAD_RESPONSE for a code other than 0, 1 and 7, and
 * GSDC_PKW_BAD_ERROR_CODE for code 7 with an error code other than 1 to 4:
 * `response` holds the code, address and value as read. */
static inline gsdc_pkw_status_t gsdc_pke_response_decode(const uint8_t pkw[GSDC_PKW_BYTES],
                                                         gsdc_pke_response_t *response)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    response->code = gsdc_pke_code(pkw);
    response->address = gsdc_pke_address(pkw);
    response->value = gsdc_u16be_get(&pkw[6]);
    switch (response->code) {
    case GSDC_PKE_NO_REQUEST:
        response->address = 0U;
        response->value = 0U;
        break;
    case GSDC_PKE_DONE:
        break;
    case GSDC_PKE_CANNOT_EXECUTE:
        if ((response->value < GSDC_PKE_ERROR_ILLEGAL_COMMAND) ||
            (response->value > GSDC_PKE_ERROR_OTHER)) {
            status = GSDC_PKW_BAD_ERROR_CODE;
        }
        break;
    default:
        status = GSDC_PKW_BAD_RESPONSE;
        break;
    }
    return status;
}

/* Encodes `response` into `pkw`: GSDC_PKW_OK. A no-request's address and
 * value are written 0. GSDC_PKW_BAD_RESPONSE for a code other than 0, 1 and
 * 7, GSDC_PKW_BAD_ERROR_CODE for code 7 with an error code other than 1 to
 * 4: `pkw` untouched. */
static inline gsdc_pkw_status_t gsdc_pke_response_encode(const gsdc_pke_response_t *response,
                                                         uint8_t pkw[GSDC_PKW_BYTES])
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    switch (response->code) {
    case GSDC_PKE_NO_REQUEST:
        gsdc_pke_words(pkw, GSDC_PKE_NO_REQUEST, 0U, 0U);
        break;
    case GSDC_PKE_DONE:
        gsdc_pke_words(pkw, GSDC_PKE_DONE, response->address, response->value);
        break;
    case GSDC_PKE_CANNOT_EXECUTE:
        if ((response->value < GSDC_PKE_ERROR_ILLEGAL_COMMAND) ||
            (response->value > GSDC_PKE_ERROR_OTHER)) {
            status = GSDC_PKW_BAD_ERROR_CODE;
        } else {
            gsdc_pke_words(pkw, GSDC_PKE_CANNOT_EXECUTE, response->address, response->value);
        }
        break;
    default:
        status = GSDC_PKW_BAD_RESPONSE;
        break;
    }
    return status;
}

/* The PKW channel with station numbers (MV810): PKW0 the target station
 * (high byte) and the source station (low byte), for the card's forwarding
 * over RS-485; PKW1 the command; PKW2 the parameter address; PKW3 the value,
 * or the count (always 1) of a read. The drive answers with the command,
 * 0x80 + the command on error. The value word of a write reply is 0 and not
 * read. */

/* The commands of PKW1. */
#define GSDC_STATION_READ 0x03U
#define GSDC_STATION_WRITE_AND_STORE 0x06U
#define GSDC_STATION_WRITE 0x07U
/* Added to the command of a failed request in the reply. */
#define GSDC_STATION_FAILED 0x80U
/* The count of a read: the card reads one parameter at a time. */
#define GSDC_STATION_READ_COUNT 1U

/* A parameter request from the master. */
typedef struct {
    /* Byte 0: the station the telegram is for. */
    uint8_t target;
    /* Byte 1: the station that sends it. */
    uint8_t source;
    /* GSDC_STATION_READ, GSDC_STATION_WRITE_AND_STORE or GSDC_STATION_WRITE. */
    uint16_t command;
    uint16_t address;
    /* The value a write writes; 0 for a read, whose count is sent as 1. */
    uint16_t value;
} gsdc_station_request_t;

/* The drive's answer to a parameter request. */
typedef struct {
    uint8_t target;
    uint8_t source;
    /* The command answered: GSDC_STATION_READ, GSDC_STATION_WRITE_AND_STORE
     * or GSDC_STATION_WRITE. */
    uint16_t command;
    /* The command failed: the reply's code is GSDC_STATION_FAILED + command. */
    bool failed;
    uint16_t address;
    /* A read's value, or the drive's error code when it failed; 0 after a
     * write. */
    uint16_t value;
} gsdc_station_response_t;

/* Whether `command` is one of the three the manual defines. */
static inline bool gsdc_station_is_command(uint32_t command)
{
    return (command == GSDC_STATION_READ) || (command == GSDC_STATION_WRITE_AND_STORE) ||
           (command == GSDC_STATION_WRITE);
}

/* Writes PKW0 to PKW3. */
static inline void gsdc_station_words(uint8_t pkw[GSDC_PKW_BYTES], uint8_t target,
                                      uint8_t source, uint16_t code, uint16_t address,
                                      uint16_t value)
{
    pkw[0] = target;
    pkw[1] = source;
    gsdc_u16be_put(&pkw[2], code);
    gsdc_u16be_put(&pkw[4], address);
    gsdc_u16be_put(&pkw[6], value);
}

/* Decodes the master's request in `pkw`. GSDC_PKW_OK: `request` holds it.
 * GSDC_PKW_BAD_COMMAND for a command the manual does not define (0 is what
 * a master sends before it has a request), GSDC_PKW_BAD_READ_COUNT for a
 * read whose count is not 1: `request` holds the words as read. */
static inline gsdc_pkw_status_t gsdc_station_request_decode(const uint8_t pkw[GSDC_PKW_BYTES],
                                                            gsdc_station_request_t *request)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    request->target = pkw[0];
    request->source = pkw[1];
    request->command = gsdc_u16be_get(&pkw[2]);
    request->address = gsdc_u16be_get(&pkw[4]);
    request->value = gsdc_u16be_get(&pkw[6]);
    if (!gsdc_station_is_command(request->command)) {
        status = GSDC_PKW_BAD_COMMAND;
    } else if (request->command == GSDC_STATION_READ) {
        if (request->value == GSDC_STATION_READ_COUNT) {
            request->value = 0U;
        } else {
            status = GSDC_PKW_BAD_READ_COUNT;
        }
    } else {
        /* A write: the value is the one to write. */
    }
    return status;
}

/* Encodes `request` into `pkw`, a read with the count 1: GSDC_PKW_OK.
 * GSDC_PKW_BAD_COMMAND, and `pkw` untouched, for a command the manual does
 * not define. */
static inline gsdc_pkw_status_t gsdc_station_request_encode(const gsdc_station_request_t *request,
                                                            uint8_t pkw[GSDC_PKW_BYTES])
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    if (!gsdc_station_is_command(request->command)) {
        status = GSDC_PKW_BAD_COMMAND;
    } else {
        uint16_t value = request->value;
        if (request->command == GSDC_STATION_READ) {
            value = (uint16_t)GSDC_STATION_READ_COUNT;
        }
        gsdc_station_words(pkw, request->target, request->source, request->command,
                           request->address, value);
    }
    return status;
}

/* Decodes the drive's reply in `pkw`. GSDC_PKW_OK: `response` holds it.
 * GSDC_PKW_BAD_COMMAND for a code that is neither a command nor
 * GSDC_STATION_FAILED + a command: `response` holds the code as its command,
 * and the words as read. */
static inline gsdc_pkw_status_t gsdc_station_response_decode(const uint8_t pkw[GSDC_PKW_BYTES],
                                                             gsdc_station_response_t *response)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    uint16_t code = gsdc_u16be_get(&pkw[2]);
    response->target = pkw[0];
    response->source = pkw[1];
    response->command = code;
    response->failed = false;
    response->address = gsdc_u16be_get(&pkw[4]);
    response->value = gsdc_u16be_get(&pkw[6]);
    if (gsdc_station_is_command(code)) {
        if (code != GSDC_STATION_READ) {
            response->value = 0U;
        }
    } else if ((code > GSDC_STATION_FAILED) &&
               gsdc_station_is_command((uint32_t)code - GSDC_STATION_FAILED)) {
        response->command = (uint16_t)((uint32_t)code - GSDC_STATION_FAILED);
        response->failed = true;
    } else {
        status = GSDC_PKW_BAD_COMMAND;
    }
    return status;
}

/* Encodes `response` into `pkw`: GSDC_PKW_OK; the value of a write that did
 * not fail is written 0. GSDC_PKW_BAD_COMMAND, and `pkw` untouched, for a
 * command the manual does not define. */
static inline gsdc_pkw_status_t gsdc_station_response_encode(
    const gsdc_station_response_t *response, uint8_t pkw[GSDC_PKW_BYTES])
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    if (!gsdc_station_is_command(response->command)) {
        status = GSDC_PKW_BAD_COMMAND;
    } else if (response->failed) {
        uint16_t code = (uint16_t)((uint32_t)response->command + GSDC_STATION_FAILED);
        gsdc_station_words(pkw, response->target, response->source, code, response->address,
                           response->value);
    } else {
        uint16_t value = 0U;
        if (response->command == GSDC_STATION_READ) {
            value = response->value;
        }
        gsdc_station_words(pkw, response->target, response->source, response->command,
                           response->address, value);
    }
    return status;
}

/* The PROFIdrive parameter channel, as the profile's PPO types carry it in
 * cyclic exchange (MICROMASTER 440 OI p.157-159, MICROMASTER 4 PROFIBUS
 * board p.25-28, MASTERDRIVES Compendium 8.2-19; docs/wire-format.md in
 * gsdc's repository quotes them). PKE: bits 15-12 the request id (AK) or
 * response id, bit 11 SPM, bits 10-0 the parameter number (PNU 0..2047).
 * IND: bits 15-8 the subindex (the array element, or the description
 * element); bits 7-0 are "not defined in PROFIDrive Profile version 2.0"
 * (Siemens drives select a page there): written 0 and not read. PWE1, PWE2:
 * a double word high word first; a word in PWE2, PWE1 written 0 and not
 * read; with response 7 the error number in PWE2. SPM, a toggle bit for
 * parameter change reports or "reserved, always 0", is written 0 and not
 * read; change reports (responses 9-12) are not carried. Requests 0-9 are
 * the profile's; 10 is reserved and 11-15 are Siemens' extensions ("not
 * defined in the PROFIDrive Profile"): refused. Every request but 0 carries
 * the subindex, whatever its id (newer SINAMICS make 1, 2, 3 the same as 6,
 * 7, 8). Nothing of a telegram without a request is read. */

/* The largest parameter number of PKE bits 10-0. */
#define GSDC_PROFIDRIVE_PNU_MAX 2047U

/* Request ids, PKE bits 15-12: the profile's 0 to 9. */
#define GSDC_PROFIDRIVE_NO_REQUEST 0U
#define GSDC_PROFIDRIVE_READ 1U
#define GSDC_PROFIDRIVE_WRITE_WORD 2U
#define GSDC_PROFIDRIVE_WRITE_DOUBLE_WORD 3U
#define GSDC_PROFIDRIVE_READ_DESCRIPTION 4U
#define GSDC_PROFIDRIVE_WRITE_DESCRIPTION 5U
#define GSDC_PROFIDRIVE_READ_ARRAY 6U
#define GSDC_PROFIDRIVE_WRITE_ARRAY_WORD 7U
#define GSDC_PROFIDRIVE_WRITE_ARRAY_DOUBLE_WORD 8U
#define GSDC_PROFIDRIVE_READ_ARRAY_LENGTH 9U

/* Response ids, PKE bits 15-12: the profile's 0 to 8. */
#define GSDC_PROFIDRIVE_NO_RESPONSE 0U
#define GSDC_PROFIDRIVE_VALUE_WORD 1U
#define GSDC_PROFIDRIVE_VALUE_DOUBLE_WORD 2U
#define GSDC_PROFIDRIVE_DESCRIPTION 3U
#define GSDC_PROFIDRIVE_ARRAY_WORD 4U
#define GSDC_PROFIDRIVE_ARRAY_DOUBLE_WORD 5U
#define GSDC_PROFIDRIVE_ARRAY_LENGTH 6U
#define GSDC_PROFIDRIVE_CANNOT_EXECUTE 7U
#define GSDC_PROFIDRIVE_NO_AUTHORITY 8U

/* Error numbers of response 7 (PWE2) that the Siemens, Danfoss and TR
 * encoTRive manuals agree on; a drive may send numbers of its own (Siemens'
 * from 101 on are device-specific). */
#define GSDC_PROFIDRIVE_ERROR_ILLEGAL_PNU 0U
#define GSDC_PROFIDRIVE_ERROR_NOT_CHANGEABLE 1U
#define GSDC_PROFIDRIVE_ERROR_LIMIT_EXCEEDED 2U
#define GSDC_PROFIDRIVE_ERROR_BAD_SUBINDEX 3U
#define GSDC_PROFIDRIVE_ERROR_NO_ARRAY 4U
#define GSDC_PROFIDRIVE_ERROR_WRONG_TYPE 5U
#define GSDC_PROFIDRIVE_ERROR_SETTING_NOT_ALLOWED 6U
#define GSDC_PROFIDRIVE_ERROR_DESCRIPTION_NOT_CHANGEABLE 7U
#define GSDC_PROFIDRIVE_ERROR_NO_MASTER_CONTROL 11U
#define GSDC_PROFIDRIVE_ERROR_KEY_WORD_MISSING 12U
#define GSDC_PROFIDRIVE_ERROR_OPERATING_STATE 17U

/* A parameter request from the master. */
typedef struct {
    /* GSDC_PROFIDRIVE_NO_REQUEST to GSDC_PROFIDRIVE_READ_ARRAY_LENGTH. */
    uint8_t id;
    /* The parameter number; 0 without a request. */
    uint16_t pnu;
    /* IND bits 15-8; 0 without a request. */
    uint8_t subindex;
    /* The value a write writes (a word below 0x10000); 0 for the others. */
    uint32_t value;
} gsdc_profidrive_request_t;

/* The drive's answer to a parameter request. */
typedef struct {
    /* GSDC_PROFIDRIVE_NO_RESPONSE to GSDC_PROFIDRIVE_NO_AUTHORITY. */
    uint8_t id;
    /* The parameter number; 0 without a response. */
    uint16_t pnu;
    uint8_t subindex;
    /* The value (a word below 0x10000), the number of array elements (6) or
     * the error number (7); 0 for 0 and 8. */
    uint32_t value;
} gsdc_profidrive_response_t;

/* The PWE words the value of an id fills: 0, 1 (PWE2) or 2 (PWE1, PWE2). */
typedef enum {
    GSDC_PROFIDRIVE_PWE_NONE = 0,
    GSDC_PROFIDRIVE_PWE_WORD,
    GSDC_PROFIDRIVE_PWE_DOUBLE_WORD
} gsdc_profidrive_pwe_t;

/* What the value of request `id` fills. */
static inline gsdc_profidrive_pwe_t gsdc_profidrive_request_pwe(uint32_t id)
{
    gsdc_profidrive_pwe_t pwe = GSDC_PROFIDRIVE_PWE_NONE;
    switch (id) {
    case GSDC_PROFIDRIVE_WRITE_WORD:
    case GSDC_PROFIDRIVE_WRITE_ARRAY_WORD:
        pwe = GSDC_PROFIDRIVE_PWE_WORD;
        break;
    case GSDC_PROFIDRIVE_WRITE_DOUBLE_WORD:
    case GSDC_PROFIDRIVE_WRITE_DESCRIPTION:
    case GSDC_PROFIDRIVE_WRITE_ARRAY_DOUBLE_WORD:
        pwe = GSDC_PROFIDRIVE_PWE_DOUBLE_WORD;
        break;
    default:
        break;
    }
    return pwe;
}

/* What the value of response `id` fills. */
static inline gsdc_profidrive_pwe_t gsdc_profidrive_response_pwe(uint32_t id)
{
    gsdc_profidrive_pwe_t pwe = GSDC_PROFIDRIVE_PWE_NONE;
    switch (id) {
    case GSDC_PROFIDRIVE_VALUE_WORD:
    case GSDC_PROFIDRIVE_ARRAY_WORD:
    case GSDC_PROFIDRIVE_ARRAY_LENGTH:
    case GSDC_PROFIDRIVE_CANNOT_EXECUTE:
        pwe = GSDC_PROFIDRIVE_PWE_WORD;
        break;
    case GSDC_PROFIDRIVE_VALUE_DOUBLE_WORD:
    case GSDC_PROFIDRIVE_DESCRIPTION:
    case GSDC_PROFIDRIVE_ARRAY_DOUBLE_WORD:
        pwe = GSDC_PROFIDRIVE_PWE_DOUBLE_WORD;
        break;
    default:
        break;
    }
    return pwe;
}

/* GSDC_PKW_OK when `pnu` fits PKE and `value` the words `pwe` names;
 * GSDC_PKW_BAD_PNU or GSDC_PKW_BAD_VALUE when not. */
static inline gsdc_pkw_status_t gsdc_profidrive_check(uint16_t pnu, gsdc_profidrive_pwe_t pwe,
                                                      uint32_t value)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    if (pnu > GSDC_PROFIDRIVE_PNU_MAX) {
        status = GSDC_PKW_BAD_PNU;
    } else if ((pwe == GSDC_PROFIDRIVE_PWE_WORD) && (value > 0xFFFFU)) {
        status = GSDC_PKW_BAD_VALUE;
    } else {
        /* Within the channel. */
    }
    return status;
}

/* Writes PKE, IND, PWE1 and PWE2 of an id, a parameter and a value that
 * fills the words `pwe` names (the others are written 0). */
static inline void gsdc_profidrive_words(uint8_t pkw[GSDC_PKW_BYTES], uint32_t id, uint16_t pnu,
                                         uint8_t subindex, gsdc_profidrive_pwe_t pwe,
                                         uint32_t value)
{
    uint16_t pwe1 = 0U;
    uint16_t pwe2 = 0U;
    if (pwe == GSDC_PROFIDRIVE_PWE_DOUBLE_WORD) {
        pwe1 = (uint16_t)(value >> 16U);
    }
    if (pwe != GSDC_PROFIDRIVE_PWE_NONE) {
        pwe2 = (uint16_t)(value & 0xFFFFU);
    }
    gsdc_u16be_put(&pkw[0], (uint16_t)(((id & 0x0FU) << 12U) | ((uint32_t)pnu & 0x07FFU)));
    pkw[2] = subindex;
    pkw[3] = 0U;
    gsdc_u16be_put(&pkw[4], pwe1);
    gsdc_u16be_put(&pkw[6], pwe2);
}

/* The id (PKE bits 15-12) of `pkw`. */
static inline uint8_t gsdc_profidrive_id(const uint8_t pkw[GSDC_PKW_BYTES])
{
    return (uint8_t)((uint32_t)pkw[0] >> 4U);
}

/* The parameter number (PKE bits 10-0) of `pkw`. */
static inline uint16_t gsdc_profidrive_pnu(const uint8_t pkw[GSDC_PKW_BYTES])
{
    return (uint16_t)((uint32_t)gsdc_u16be_get(&pkw[0]) & 0x07FFU);
}

/* The value of `pkw` in the words `pwe` names; 0 for none. */
static inline uint32_t gsdc_profidrive_value(const uint8_t pkw[GSDC_PKW_BYTES],
                                             gsdc_profidrive_pwe_t pwe)
{
    uint32_t value = 0U;
    if (pwe == GSDC_PROFIDRIVE_PWE_WORD) {
        value = gsdc_u16be_get(&pkw[6]);
    } else if (pwe == GSDC_PROFIDRIVE_PWE_DOUBLE_WORD) {
        value = ((uint32_t)gsdc_u16be_get(&pkw[4]) << 16U) | (uint32_t)gsdc_u16be_get(&pkw[6]);
    } else {
        /* No value. */
    }
    return value;
}

/* Decodes the master's request in `pkw`. GSDC_PKW_OK: `request` holds it.
 * GSDC_PKW_BAD_COMMAND for an id from 10 on: `request` holds the id, the
 * parameter number and the subindex the drive answers
 * GSDC_PROFIDRIVE_CANNOT_EXECUTE about (Siemens manuals give error 106,
 * request not implemented, after requests 5, 10 and 15), and value 0. */
static inline gsdc_pkw_status_t
gsdc_profidrive_request_decode(const uint8_t pkw[GSDC_PKW_BYTES],
                               gsdc_profidrive_request_t *request)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    request->id = gsdc_profidrive_id(pkw);
    request->pnu = gsdc_profidrive_pnu(pkw);
    request->subindex = pkw[2];
    request->value = gsdc_profidrive_value(pkw, gsdc_profidrive_request_pwe(request->id));
    if (request->id == GSDC_PROFIDRIVE_NO_REQUEST) {
        request->pnu = 0U;
        request->subindex = 0U;
    } else if (request->id > GSDC_PROFIDRIVE_READ_ARRAY_LENGTH) {
        status = GSDC_PKW_BAD_COMMAND;
    } else {
        /* One of the profile's requests. */
    }
    return status;
}

/* Encodes `request` into `pkw`: GSDC_PKW_OK. A no-request is written all 0.
 * GSDC_PKW_BAD_COMMAND for an id from 10 on, GSDC_PKW_BAD_PNU for a
 * parameter number beyond GSDC_PROFIDRIVE_PNU_MAX, GSDC_PKW_BAD_VALUE for a
 * word write of a value beyond 0xFFFF: `pkw` untouched. */
static inline gsdc_pkw_status_t
gsdc_profidrive_request_encode(const gsdc_profidrive_request_t *request,
                               uint8_t pkw[GSDC_PKW_BYTES])
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    gsdc_profidrive_pwe_t pwe = gsdc_profidrive_request_pwe(request->id);
    if (request->id == GSDC_PROFIDRIVE_NO_REQUEST) {
        gsdc_profidrive_words(pkw, GSDC_PROFIDRIVE_NO_REQUEST, 0U, 0U, GSDC_PROFIDRIVE_PWE_NONE,
                              0U);
    } else if (request->id > GSDC_PROFIDRIVE_READ_ARRAY_LENGTH) {
        status = GSDC_PKW_BAD_COMMAND;
    } else {
        status = gsdc_profidrive_check(request->pnu, pwe, request->value);
        if (status == GSDC_PKW_OK) {
            gsdc_profidrive_words(pkw, request->id, request->pnu, request->subindex, pwe,
                                  request->value);
        }
    }
    return status;
}

/* Decodes the drive's response in `pkw`. GSDC_PKW_OK: `response` holds it.
 * GSDC_PKW_CHANGE_REPORT for a parameter change report (9 to 12),
 * GSDC_PKW_BAD_RESPONSE for 13 to 15: `response` holds the id, the
 * parameter number and the subindex, and value 0. */
static inline gsdc_pkw_status_t
gsdc_profidrive_response_decode(const uint8_t pkw[GSDC_PKW_BYTES],
                                gsdc_profidrive_response_t *response)
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    response->id = gsdc_profidrive_id(pkw);
    response->pnu = gsdc_profidrive_pnu(pkw);
    response->subindex = pkw[2];
    response->value = gsdc_profidrive_value(pkw, gsdc_profidrive_response_pwe(response->id));
    if (response->id == GSDC_PROFIDRIVE_NO_RESPONSE) {
        response->pnu = 0U;
        response->subindex = 0U;
    } else if (response->id <= GSDC_PROFIDRIVE_NO_AUTHORITY) {
        /* One of the profile's responses. */
    } else if (response->id <= 12U) {
        status = GSDC_PKW_CHANGE_REPORT;
    } else {
        status = GSDC_PKW_BAD_RESPONSE;
    }
    return status;
}

/* Encodes `response` into `pkw`: GSDC_PKW_OK. No response is written all 0.
 * GSDC_PKW_BAD_RESPONSE for an id from 9 on, GSDC_PKW_BAD_PNU for a
 * parameter number beyond GSDC_PROFIDRIVE_PNU_MAX, GSDC_PKW_BAD_VALUE for a
 * word (a value, a count, an error number) beyond 0xFFFF: `pkw` untouched. */
static inline gsdc_pkw_status_t
gsdc_profidrive_response_encode(const gsdc_profidrive_response_t *response,
                                uint8_t pkw[GSDC_PKW_BYTES])
{
    gsdc_pkw_status_t status = GSDC_PKW_OK;
    gsdc_profidrive_pwe_t pwe = gsdc_profidrive_response_pwe(response->id);
    if (response->id == GSDC_PROFIDRIVE_NO_RESPONSE) {
        gsdc_profidrive_words(pkw, GSDC_PROFIDRIVE_NO_RESPONSE, 0U, 0U, GSDC_PROFIDRIVE_PWE_NONE,
                              0U);
    } else if (response->id > GSDC_PROFIDRIVE_NO_AUTHORITY) {
        status = GSDC_PKW_BAD_RESPONSE;
    } else {
        status = gsdc_profidrive_check(response->pnu, pwe, response->value);
        if (status == GSDC_PKW_OK) {
            gsdc_profidrive_words(pkw, response->id, response->pnu, response->subindex, pwe,
                                  response->value);
        }
    }
    return status;
}

/* ------------------------------------------------------------------------
 * Gateways: cards that carry the data of the nodes of a second bus. The
 * master sets how many nodes are in use and the words each one carries each
 * way (User_Prm_Data), plugs word modules until its input and output equal
 * the nodes' totals (the config bytes of Chk_Cfg), and reads a diagnosis
 * block of type, node and code. */

/* How a user parameter is stored: one byte, two bytes big-endian, or some
 * bits of one byte, whose other bits other parameters may hold. */
typedef enum {
    GSDC_PRM_UNSIGNED8 = 0,
    GSDC_PRM_UNSIGNED16,
    GSDC_PRM_BITS
} gsdc_prm_type_t;

/* A user parameter: where it lies in User_Prm_Data, how it is stored, the
 * values it may hold and its default. A layout's initializers give the
 * members in this order. */
typedef struct {
    size_t offset;
    gsdc_prm_type_t type;
    /* The bits of GSDC_PRM_BITS, first_bit <= last_bit < 8; 0 for the others. */
    uint8_t first_bit;
    uint8_t last_bit;
    uint8_t min;
    uint8_t max;
    uint8_t default_value;
} gsdc_prm_field_t;

/* Bytes of `field` from its offset on. */
static inline size_t gsdc_prm_field_len(const gsdc_prm_field_t *field)
{
    size_t len = 1U;
    if (field->type == GSDC_PRM_UNSIGNED16) {
        len = 2U;
    }
    return len;
}

/* The mask of bits `first` to `last` (below 8) of a byte. */
static inline uint32_t gsdc_prm_bit_mask(unsigned int first, unsigned int last)
{
    return ((0xFFU >> ((7U - (last - first)) & 7U)) << (first & 7U)) & 0xFFU;
}

/* Whether `field` may hold `value`. */
static inline bool gsdc_prm_field_allows(const gsdc_prm_field_t *field, uint16_t value)
{
    return (value >= field->min) && (value <= field->max);
}

/* GSDC_PRM_LENGTH when `field` does not lie within `len` bytes, else
 * GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_prm_field_fits(const gsdc_prm_field_t *field, size_t len)
{
    gsdc_prm_result_t result = gsdc_prm_ok();
    size_t field_len = gsdc_prm_field_len(field);
    if ((field->offset > len) || ((len - field->offset) < field_len)) {
        result.fault = GSDC_PRM_LENGTH;
        result.expected = field->offset + field_len;
        result.found = len;
    }
    return result;
}

/* The value of `field` as `bytes` store it, not checked: the field lies
 * within the bytes. */
static inline uint16_t gsdc_prm_field_get(const gsdc_prm_field_t *field, const uint8_t *bytes)
{
    uint16_t value;
    switch (field->type) {
    case GSDC_PRM_UNSIGNED16:
        value = gsdc_u16be_get(&bytes[field->offset]);
        break;
    case GSDC_PRM_BITS:
        value = (uint16_t)(((uint32_t)bytes[field->offset] &
                            gsdc_prm_bit_mask(field->first_bit, field->last_bit)) >>
                           (field->first_bit & 7U));
        break;
    default:
        value = bytes[field->offset];
        break;
    }
    return value;
}

/* Checks `field` in `bytes`, `len` bytes long: GSDC_PRM_LENGTH when it lies
 * past the end, GSDC_PRM_NOT_ALLOWED (its offset and the value as stored)
 * when its range does not hold the value, else GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_prm_field_check(const gsdc_prm_field_t *field,
                                                     const uint8_t *bytes, size_t len)
{
    gsdc_prm_result_t result = gsdc_prm_field_fits(field, len);
    if (result.fault == GSDC_PRM_OK) {
        uint16_t value = gsdc_prm_field_get(field, bytes);
        if (!gsdc_prm_field_allows(field, value)) {
            result.fault = GSDC_PRM_NOT_ALLOWED;
            result.offset = field->offset;
            result.value = value;
        }
    }
    return result;
}

/* Checks a write of `value` to `field` in `len` bytes: GSDC_PRM_NOT_ALLOWED
 * (its offset and the value) when its range does not hold the value,
 * GSDC_PRM_LENGTH when it lies past the end, else GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_prm_field_check_value(const gsdc_prm_field_t *field,
                                                           size_t len, uint8_t value)
{
    gsdc_prm_result_t result = gsdc_prm_ok();
    if (!gsdc_prm_field_allows(field, value)) {
        result.fault = GSDC_PRM_NOT_ALLOWED;
        result.offset = field->offset;
        result.value = value;
    } else {
        result = gsdc_prm_field_fits(field, len);
    }
    return result;
}

/* Writes `value` to `field` in `bytes`, leaving the other bits of a byte the
 * field shares: gsdc_prm_field_check_value has passed it. */
static inline void gsdc_prm_field_put(const gsdc_prm_field_t *field, uint8_t *bytes,
                                      uint8_t value)
{
    switch (field->type) {
    case GSDC_PRM_UNSIGNED16:
        gsdc_u16be_put(&bytes[field->offset], value);
        break;
    case GSDC_PRM_BITS: {
        uint32_t mask = gsdc_prm_bit_mask(field->first_bit, field->last_bit);
        uint32_t bits = ((uint32_t)value << (field->first_bit & 7U)) & mask;
        bytes[field->offset] = (uint8_t)(((uint32_t)bytes[field->offset] & ~mask) | bits);
        break;
    }
    default:
        bytes[field->offset] = value;
        break;
    }
}

/* A gateway's node parameters, node `first_node` first, and its data
 * limits in bytes: what a layout's <prefix>_node_params gives. */
typedef struct {
    uint8_t first_node;
    /* The node numbers that have parameters: `input_words` and
     * `output_words` have one each. */
    size_t nodes;
    const gsdc_prm_field_t *node_count;
    const gsdc_prm_field_t *input_words;
    const gsdc_prm_field_t *output_words;
    size_t max_input_len;
    size_t max_output_len;
} gsdc_node_params_t;

/* Checks the node parameters in User_Prm_Data, `len` bytes, as
 * gsdc_prm_field_check does: the count, then each node's input words, then
 * each node's output words; the first fault found. */
static inline gsdc_prm_result_t gsdc_nodes_check(const gsdc_node_params_t *params,
                                                 const uint8_t *bytes, size_t len)
{
    gsdc_prm_result_t result = gsdc_prm_field_check(params->node_count, bytes, len);
    size_t i;
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < params->nodes); i++) {
        result = gsdc_prm_field_check(&params->input_words[i], bytes, len);
    }
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < params->nodes); i++) {
        result = gsdc_prm_field_check(&params->output_words[i], bytes, len);
    }
    return result;
}

/* The node parameters gsdc_nodes_check has passed: the count, and the
 * words of each node each way (`params->nodes` each). */
static inline void gsdc_nodes_get(const gsdc_node_params_t *params, const uint8_t *bytes,
                                  uint8_t *count, uint8_t *input, uint8_t *output)
{
    size_t i;
    *count = (uint8_t)gsdc_prm_field_get(params->node_count, bytes);
    for (i = 0U; i < params->nodes; i++) {
        input[i] = (uint8_t)gsdc_prm_field_get(&params->input_words[i], bytes);
        output[i] = (uint8_t)gsdc_prm_field_get(&params->output_words[i], bytes);
    }
}

/* Writes the count and each node's words (`params->nodes` each) into
 * User_Prm_Data, `len` bytes, each value checked first as
 * gsdc_prm_field_check_value checks it, in the order gsdc_nodes_check reads
 * them: on a fault nothing is written. Bytes no parameter holds are left as
 * they are. */
static inline gsdc_prm_result_t gsdc_nodes_put(const gsdc_node_params_t *params, uint8_t count,
                                               const uint8_t *input, const uint8_t *output,
                                               uint8_t *bytes, size_t len)
{
    gsdc_prm_result_t result = gsdc_prm_field_check_value(params->node_count, len, count);
    size_t i;
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < params->nodes); i++) {
        result = gsdc_prm_field_check_value(&params->input_words[i], len, input[i]);
    }
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < params->nodes); i++) {
        result = gsdc_prm_field_check_value(&params->output_words[i], len, output[i]);
    }
    if (result.fault == GSDC_PRM_OK) {
        gsdc_prm_field_put(params->node_count, bytes, count);
        for (i = 0U; i < params->nodes; i++) {
            gsdc_prm_field_put(&params->input_words[i], bytes, input[i]);
            gsdc_prm_field_put(&params->output_words[i], bytes, output[i]);
        }
    }
    return result;
}

/* Which way a node's words go: in, the node sends them (the master's
 * input); out, it receives them. */
typedef enum {
    GSDC_DIRECTION_NONE = 0,
    GSDC_DIRECTION_IN,
    GSDC_DIRECTION_OUT
} gsdc_direction_t;

/* Why a node configuration, or the config bytes of the plugged modules,
 * were refused. */
typedef enum {
    GSDC_TOTALS_OK = 0,
    /* More nodes (`count`), or fewer, than the count's parameter allows. */
    GSDC_TOTALS_NODE_COUNT,
    /* Node `node` carries `words` words `direction`, which its parameter
     * does not allow. */
    GSDC_TOTALS_WORDS,
    /* Node `node`, past the count, carries words. */
    GSDC_TOTALS_UNUSED_NODE,
    /* `len` bytes `direction`; the gateway carries at most `max`. */
    GSDC_TOTALS_TOO_LONG,
    /* Config byte `at` (0 = the first), `byte`, is no module's. */
    GSDC_TOTALS_UNKNOWN_MODULE,
    /* `len` modules; Max_Module is `max`. */
    GSDC_TOTALS_TOO_MANY_MODULES
} gsdc_totals_fault_t;

/* The words of input and output a node configuration or the plugged modules
 * carry, or why they were refused: the fault, and the fields that fault
 * names (the others are 0, the words too). */
typedef struct {
    gsdc_totals_fault_t fault;
    /* GSDC_TOTALS_OK: the words each way. */
    uint16_t input_words;
    uint16_t output_words;
    uint8_t count;
    uint8_t node;
    gsdc_direction_t direction;
    uint8_t words;
    size_t len;
    size_t max;
    size_t at;
    uint8_t byte;
} gsdc_totals_t;

/* GSDC_TOTALS_OK, no words. */
static inline gsdc_totals_t gsdc_totals_ok(void)
{
    gsdc_totals_t totals;
    totals.fault = GSDC_TOTALS_OK;
    totals.input_words = 0U;
    totals.output_words = 0U;
    totals.count = 0U;
    totals.node = 0U;
    totals.direction = GSDC_DIRECTION_NONE;
    totals.words = 0U;
    totals.len = 0U;
    totals.max = 0U;
    totals.at = 0U;
    totals.byte = 0U;
    return totals;
}

/* Bytes of input the totals carry: the master's input modules carry as
 * many. */
static inline size_t gsdc_totals_input_len(const gsdc_totals_t *totals)
{
    return 2U * (size_t)totals->input_words;
}

/* Bytes of output the totals carry. */
static inline size_t gsdc_totals_output_len(const gsdc_totals_t *totals)
{
    return 2U * (size_t)totals->output_words;
}

/* Whether the plugged modules carry what the nodes do: both accepted, with
 * the same words each way. The gateway takes the configuration then. */
static inline bool gsdc_totals_match(const gsdc_totals_t *nodes, const gsdc_totals_t *modules)
{
    return (nodes->fault == GSDC_TOTALS_OK) && (modules->fault == GSDC_TOTALS_OK) &&
           (nodes->input_words == modules->input_words) &&
           (nodes->output_words == modules->output_words);
}

/* The words of one node `direction` do not fit its parameter: the fault. */
static inline gsdc_totals_t gsdc_totals_words_fault(uint8_t node, gsdc_direction_t direction,
                                                    uint8_t words)
{
    gsdc_totals_t totals = gsdc_totals_ok();
    totals.fault = GSDC_TOTALS_WORDS;
    totals.node = node;
    totals.direction = direction;
    totals.words = words;
    return totals;
}

/* `len` bytes `direction`, more than `max`: GSDC_TOTALS_TOO_LONG; else
 * GSDC_TOTALS_OK. */
static inline gsdc_totals_t gsdc_totals_check_len(gsdc_direction_t direction, size_t len,
                                                  size_t max)
{
    gsdc_totals_t totals = gsdc_totals_ok();
    if (len > max) {
        totals.fault = GSDC_TOTALS_TOO_LONG;
        totals.direction = direction;
        totals.len = len;
        totals.max = max;
    }
    return totals;
}

/* The totals of the first `count` nodes' words (`input` and `output`,
 * `params->nodes` each): each within its parameter's range, the nodes past
 * the count without words, and each total within the gateway's limit. Pure:
 * it reads its arguments only. */
static inline gsdc_totals_t gsdc_node_totals(const gsdc_node_params_t *params, uint8_t count,
                                             const uint8_t *input, const uint8_t *output)
{
    gsdc_totals_t totals = gsdc_totals_ok();
    uint32_t input_words = 0U;
    uint32_t output_words = 0U;
    size_t i;
    if (!gsdc_prm_field_allows(params->node_count, count) || ((size_t)count > params->nodes)) {
        totals.fault = GSDC_TOTALS_NODE_COUNT;
        totals.count = count;
    }
    for (i = 0U; (totals.fault == GSDC_TOTALS_OK) && (i < params->nodes); i++) {
        uint8_t node = (uint8_t)((size_t)params->first_node + i);
        if (i >= (size_t)count) {
            if ((input[i] != 0U) || (output[i] != 0U)) {
                totals.fault = GSDC_TOTALS_UNUSED_NODE;
                totals.node = node;
            }
        } else if (!gsdc_prm_field_allows(&params->input_words[i], input[i])) {
            totals = gsdc_totals_words_fault(node, GSDC_DIRECTION_IN, input[i]);
        } else if (!gsdc_prm_field_allows(&params->output_words[i], output[i])) {
            totals = gsdc_totals_words_fault(node, GSDC_DIRECTION_OUT, output[i]);
        } else {
            input_words += input[i];
            output_words += output[i];
        }
    }
    if (totals.fault == GSDC_TOTALS_OK) {
        totals = gsdc_totals_check_len(GSDC_DIRECTION_IN, 2U * (size_t)input_words,
                                       params->max_input_len);
    }
    if (totals.fault == GSDC_TOTALS_OK) {
        totals = gsdc_totals_check_len(GSDC_DIRECTION_OUT, 2U * (size_t)output_words,
                                       params->max_output_len);
    }
    if (totals.fault == GSDC_TOTALS_OK) {
        totals.input_words = (uint16_t)input_words;
        totals.output_words = (uint16_t)output_words;
    }
    return totals;
}

/* Where node `node`'s words start in the data one way, in bytes, when the
 * nodes in use (the first `count`) follow each other in ascending node
 * number: after the words of the nodes before it; `words` holds each
 * node's words that way. false, and `offset` not written, for a node not in
 * use. */
static inline bool gsdc_node_offset(const gsdc_node_params_t *params, uint8_t count,
                                    const uint8_t *words, uint8_t node, size_t *offset)
{
    size_t index = (size_t)node - (size_t)params->first_node;
    bool in_use = (node >= params->first_node) && (index < (size_t)count) &&
                  (index < params->nodes);
    if (in_use) {
        size_t bytes = 0U;
        size_t i;
        for (i = 0U; i < index; i++) {
            bytes += 2U * (size_t)words[i];
        }
        *offset = bytes;
    }
    return in_use;
}

/* Whether `byte` is one of the `count` bytes of `bytes`. */
static inline bool gsdc_byte_listed(uint8_t byte, const uint8_t *bytes, size_t count)
{
    bool found = false;
    size_t i;
    for (i = 0U; (i < count) && !found; i++) {
        found = (bytes[i] == byte);
    }
    return found;
}

/* The words of input and output the plugged modules carry: `config` holds
 * `len` config identifier bytes, one per module, each one of the `count`
 * bytes of `modules` (general identifiers of words: bits 5-4 the direction,
 * 01 input and 10 output, bits 3-0 the words - 1). Refused: a byte no module
 * has, or more than `max_modules` bytes. */
static inline gsdc_totals_t gsdc_config_totals(const uint8_t *config, size_t len,
                                               const uint8_t *modules, size_t count,
                                               size_t max_modules)
{
    gsdc_totals_t totals = gsdc_totals_ok();
    uint32_t input_words = 0U;
    uint32_t output_words = 0U;
    size_t i;
    if (len > max_modules) {
        totals.fault = GSDC_TOTALS_TOO_MANY_MODULES;
        totals.len = len;
        totals.max = max_modules;
    }
    for (i = 0U; (totals.fault == GSDC_TOTALS_OK) && (i < len); i++) {
        uint32_t words = ((uint32_t)config[i] & 0x0FU) + 1U;
        uint32_t way = (uint32_t)config[i] & 0x30U;
        if (!gsdc_byte_listed(config[i], modules, count) || ((way != 0x10U) && (way != 0x20U))) {
            totals.fault = GSDC_TOTALS_UNKNOWN_MODULE;
            totals.at = i;
            totals.byte = config[i];
        } else if (way == 0x10U) {
            input_words += words;
        } else {
            output_words += words;
        }
    }
    if (totals.fault == GSDC_TOTALS_OK) {
        totals.input_words = (uint16_t)input_words;
        totals.output_words = (uint16_t)output_words;
    }
    return totals;
}

/* Why a gateway's diagnosis block was refused, or a diagnosis could not be
 * encoded. */
typedef enum {
    GSDC_DIAG_OK = 0,
    /* The header, `value`, is not a device-related block's (bits 7-6 00). */
    GSDC_DIAG_HEADER,
    /* `found` bytes; the header or the type needs `expected`. */
    GSDC_DIAG_SHORT,
    /* The header says `found` bytes; blocks of the type have `expected`. */
    GSDC_DIAG_LENGTH,
    /* A type, `value`, the gateway does not report. */
    GSDC_DIAG_TYPE,
    /* A node number, `value`, the gateway does not have. */
    GSDC_DIAG_NODE,
    /* A code, `value`, type `kind` does not list. */
    GSDC_DIAG_CODE
} gsdc_diag_fault_t;

/* What decoding or encoding a diagnosis found: the fault, and the fields
 * that fault names (the others are 0). */
typedef struct {
    gsdc_diag_fault_t fault;
    size_t expected;
    size_t found;
    uint8_t kind;
    uint16_t value;
} gsdc_diag_result_t;

/* Whether `value` is one of a set's values: a layout's <set>_is_value. */
typedef bool (*gsdc_is_value_t)(uint16_t value);

/* A type of a gateway's diagnosis: its value, the bytes of its blocks (the
 * header included), and its code: one byte, one of the values `is_code`
 * accepts (bytes only), or, where `is_code` is NULL, a 16-bit number, high
 * byte first. */
typedef struct {
    uint8_t value;
    uint8_t len;
    gsdc_is_value_t is_code;
} gsdc_diag_type_t;

/* Where a gateway's diagnosis block holds the type, the node and the code
 * (the header being byte 0), the node numbers, and the types there are:
 * what a layout's <prefix>_diag_layout gives. */
typedef struct {
    size_t type_at;
    size_t node_at;
    size_t code_at;
    uint8_t first_node;
    uint8_t last_node;
    const gsdc_diag_type_t *types;
    size_t type_count;
} gsdc_diag_layout_t;

/* GSDC_DIAG_OK. */
static inline gsdc_diag_result_t gsdc_diag_ok(void)
{
    gsdc_diag_result_t result;
    result.fault = GSDC_DIAG_OK;
    result.expected = 0U;
    result.found = 0U;
    result.kind = 0U;
    result.value = 0U;
    return result;
}

/* A fault that names one value (GSDC_DIAG_HEADER, _TYPE, _NODE, _CODE). */
static inline gsdc_diag_result_t gsdc_diag_value_fault(gsdc_diag_fault_t fault, uint8_t kind,
                                                       uint16_t value)
{
    gsdc_diag_result_t result = gsdc_diag_ok();
    result.fault = fault;
    result.kind = kind;
    result.value = value;
    return result;
}

/* A fault of lengths (GSDC_DIAG_SHORT, GSDC_DIAG_LENGTH). */
static inline gsdc_diag_result_t gsdc_diag_len_fault(gsdc_diag_fault_t fault, size_t expected,
                                                     size_t found)
{
    gsdc_diag_result_t result = gsdc_diag_ok();
    result.fault = fault;
    result.expected = expected;
    result.found = found;
    return result;
}

/* The type `kind` of `layout`, or NULL when the gateway reports no such
 * type. */
static inline const gsdc_diag_type_t *gsdc_diag_type(const gsdc_diag_layout_t *layout,
                                                     uint32_t kind)
{
    const gsdc_diag_type_t *found = NULL;
    size_t i;
    for (i = 0U; (i < layout->type_count) && (found == NULL); i++) {
        if (layout->types[i].value == kind) {
            found = &layout->types[i];
        }
    }
    return found;
}

/* Bytes of the code of `type`. */
static inline size_t gsdc_diag_code_len(const gsdc_diag_type_t *type)
{
    size_t len = 1U;
    if (type->is_code == NULL) {
        len = 2U;
    }
    return len;
}

/* GSDC_DIAG_NODE when `node` is not one of the gateway's node numbers. */
static inline gsdc_diag_result_t gsdc_diag_check_node(const gsdc_diag_layout_t *layout,
                                                      uint8_t node)
{
    gsdc_diag_result_t result = gsdc_diag_ok();
    if ((node < layout->first_node) || (node > layout->last_node)) {
        result = gsdc_diag_value_fault(GSDC_DIAG_NODE, 0U, node);
    }
    return result;
}

/* GSDC_DIAG_CODE when `type` has one-byte codes and does not list `code`. */
static inline gsdc_diag_result_t gsdc_diag_check_code(const gsdc_diag_type_t *type,
                                                      uint16_t code)
{
    gsdc_diag_result_t result = gsdc_diag_ok();
    if ((type->is_code != NULL) && !type->is_code(code)) {
        result = gsdc_diag_value_fault(GSDC_DIAG_CODE, type->value, code);
    }
    return result;
}

/* Checks the header of a block of `len` bytes and the bytes it says the
 * block has: the length the header says, else a fault. */
static inline gsdc_diag_result_t gsdc_diag_check_header(const uint8_t *block, size_t len,
                                                        size_t *block_len)
{
    gsdc_diag_result_t result = gsdc_diag_ok();
    if (len == 0U) {
        result = gsdc_diag_len_fault(GSDC_DIAG_SHORT, 1U, 0U);
    } else if ((block[0] & 0xC0U) != 0U) {
        result = gsdc_diag_value_fault(GSDC_DIAG_HEADER, 0U, block[0]);
    } else if ((size_t)block[0] > len) {
        result = gsdc_diag_len_fault(GSDC_DIAG_SHORT, block[0], len);
    } else {
        *block_len = block[0];
    }
    return result;
}

/* Decodes a gateway's device-related diagnosis block, `len` bytes with the
 * header byte first; bytes past the length the header says belong to what
 * follows and are not read. GSDC_DIAG_OK: `kind`, `node` and `code` hold the
 * block; else they are not written. */
static inline gsdc_diag_result_t gsdc_diag_decode(const gsdc_diag_layout_t *layout,
                                                  const uint8_t *block, size_t len,
                                                  uint8_t *kind, uint8_t *node, uint16_t *code)
{
    size_t block_len = 0U;
    const gsdc_diag_type_t *type = NULL;
    gsdc_diag_result_t result = gsdc_diag_check_header(block, len, &block_len);
    if ((result.fault == GSDC_DIAG_OK) && (layout->type_at >= block_len)) {
        result = gsdc_diag_len_fault(GSDC_DIAG_SHORT, layout->type_at + 1U, block_len);
    }
    if ((result.fault == GSDC_DIAG_OK) && (layout->node_at >= block_len)) {
        result = gsdc_diag_len_fault(GSDC_DIAG_SHORT, layout->node_at + 1U, block_len);
    }
    if (result.fault == GSDC_DIAG_OK) {
        type = gsdc_diag_type(layout, block[layout->type_at]);
        if (type == NULL) {
            result = gsdc_diag_value_fault(GSDC_DIAG_TYPE, 0U, block[layout->type_at]);
        }
    }
    if (result.fault == GSDC_DIAG_OK) {
        result = gsdc_diag_check_node(layout, block[layout->node_at]);
    }
    if ((result.fault == GSDC_DIAG_OK) && (type != NULL) && (block_len != type->len)) {
        result = gsdc_diag_len_fault(GSDC_DIAG_LENGTH, type->len, block_len);
    }
    if ((result.fault == GSDC_DIAG_OK) && (type != NULL) &&
        (layout->code_at + gsdc_diag_code_len(type) > block_len)) {
        result = gsdc_diag_len_fault(GSDC_DIAG_SHORT, layout->code_at + gsdc_diag_code_len(type),
                                     block_len);
    }
    if ((result.fault == GSDC_DIAG_OK) && (type != NULL)) {
        uint16_t value = block[layout->code_at];
        if (gsdc_diag_code_len(type) == 2U) {
            value = gsdc_u16be_get(&block[layout->code_at]);
        }
        result = gsdc_diag_check_code(type, value);
        if (result.fault == GSDC_DIAG_OK) {
            *kind = type->value;
            *node = block[layout->node_at];
            *code = value;
        }
    }
    return result;
}

/* Encodes a diagnosis of type `kind` at `node` with `code` into `block`,
 * which has room for the longest block: the header, the type, the node and
 * the code, the block's other bytes 0, and `*len` its length. GSDC_DIAG_TYPE,
 * GSDC_DIAG_NODE or GSDC_DIAG_CODE for what the gateway does not report:
 * nothing is written then. */
static inline gsdc_diag_result_t gsdc_diag_encode(const gsdc_diag_layout_t *layout, uint8_t kind,
                                                  uint8_t node, uint16_t code, uint8_t *block,
                                                  size_t *len)
{
    const gsdc_diag_type_t *type = gsdc_diag_type(layout, kind);
    gsdc_diag_result_t result = gsdc_diag_ok();
    if (type == NULL) {
        result = gsdc_diag_value_fault(GSDC_DIAG_TYPE, 0U, kind);
    } else {
        result = gsdc_diag_check_node(layout, node);
    }
    if ((result.fault == GSDC_DIAG_OK) && (type != NULL)) {
        result = gsdc_diag_check_code(type, code);
    }
    if ((result.fault == GSDC_DIAG_OK) && (type != NULL)) {
        size_t i;
        for (i = 0U; i < type->len; i++) {
            block[i] = 0U;
        }
        block[0] = type->len;
        block[layout->type_at] = kind;
        block[layout->node_at] = node;
        if (gsdc_diag_code_len(type) == 2U) {
            gsdc_u16be_put(&block[layout->code_at], code);
        } else {
            block[layout->code_at] = (uint8_t)code;
        }
        *len = type->len;
    }
    return result;
}

/* ------------------------------------------------------------------------
 * Device tables: what a PROFIBUS-DP slave and a PROFINET IO device built
 * from a layout need to know of the device, the same types in every layout
 * (<prefix>_dp_device() and <prefix>_pn_device()), so one slave or device
 * serves any description. A list is a pointer and its count (NULL and 0
 * when empty). */

/* Which PKW codec of this header the card's telegrams carry. */
typedef enum {
    GSDC_PKW_CODEC_NONE = 0,
    /* gsdc_pke_* */
    GSDC_PKW_CODEC_PKE_IND_PWE,
    /* gsdc_station_* */
    GSDC_PKW_CODEC_STATION_COMMAND,
    /* gsdc_profidrive_* */
    GSDC_PKW_CODEC_PROFIDRIVE
} gsdc_pkw_codec_t;

/* A `Module` of the GSD: its name as the GSD writes it, its config bytes as
 * Chk_Cfg carries them, its bytes of input (the slave sends them) and of
 * output, whether its telegrams start with the PKW channel, its PZD words
 * each way (0 for a gateway's module, whose words are the nodes'), and the
 * bytes of F-parameters a PROFIsafe module's master sends after the
 * device's User_Prm_Data when it is plugged (F_Ext_Module_Prm_Data_Len; 0
 * for any other module), which the F-device's PROFIsafe layer reads. */
typedef struct {
    const char *name;
    const uint8_t *config;
    size_t config_count;
    size_t input_len;
    size_t output_len;
    bool pkw;
    size_t pzd_words;
    size_t f_parameter_len;
} gsdc_dp_module_t;

/* How a parameter is stored, as the GSD names it. */
typedef enum {
    GSDC_PRM_DATA_TYPE_UNSIGNED8 = 0,
    GSDC_PRM_DATA_TYPE_UNSIGNED16,
    /* Bit(first_bit) of the byte at the offset. */
    GSDC_PRM_DATA_TYPE_BIT,
    /* BitArea(first_bit-last_bit) of the byte at the offset. */
    GSDC_PRM_DATA_TYPE_BIT_AREA
} gsdc_prm_data_type_t;

/* An ExtUserPrmData where User_Prm_Data holds it: its name as the GSD
 * writes it, its offset, type and bits (0 and 7, or 15, for a number), its
 * default, and what it may hold: min to max, and one of `values` when the
 * GSD lists them. */
typedef struct {
    const char *name;
    size_t offset;
    gsdc_prm_data_type_t data_type;
    uint8_t first_bit;
    uint8_t last_bit;
    uint16_t default_value;
    uint16_t min;
    uint16_t max;
    const uint16_t *values;
    size_t values_count;
} gsdc_dp_param_t;

/* User_Prm_Data: its length, the DPV1 status bytes at its start (NULL
 * without DPV1) and every ExtUserPrmData of the GSD. */
typedef struct {
    size_t len;
    const uint8_t *dpv1_status;
    size_t dpv1_status_count;
    const gsdc_dp_param_t *params;
    size_t params_count;
} gsdc_user_prm_t;

/* A gateway's node totals: the bytes of input and output the nodes in use
 * carry, as User_Prm_Data (`len` bytes) sets them; false when it is refused. */
typedef bool (*gsdc_node_totals_t)(const uint8_t *user_prm, size_t len, size_t *input_len,
                                   size_t *output_len);

/* A PZD word and the parameter of User_Prm_Data whose value is the drive
 * parameter it carries: the word's number in the telegram (from 1, PZD1
 * following the PKW channel) and the parameter's place in the user_prm's
 * params. */
typedef struct {
    uint8_t word;
    size_t param;
} gsdc_pzd_param_t;

/* A Unit_Diag_Area of the GSD: bits first_bit to last_bit after the header
 * (gsdc_diag_area_get and gsdc_diag_area_set read and write them) and the
 * values the GSD gives a text. */
typedef struct {
    uint16_t first_bit;
    uint16_t last_bit;
    const uint16_t *values;
    size_t values_count;
} gsdc_dp_diag_area_t;

/* A drive's card's device-related diagnosis block: its bytes with the
 * header (whose value is the same number: bits 7-6 = 00) and every
 * Unit_Diag_Area of the GSD. */
typedef struct {
    size_t len;
    const gsdc_dp_diag_area_t *areas;
    size_t areas_count;
} gsdc_dp_diagnosis_t;

/* The block's header byte: a device-related block (bits 7-6 = 00) of len
 * bytes. */
static inline uint8_t gsdc_dp_diagnosis_header(const gsdc_dp_diagnosis_t *d)
{
    return (uint8_t)(d->len & 0x3FU);
}

/* A node number of a gateway and the places in the user_prm's params of
 * the words it sends (the master's input) and receives. */
typedef struct {
    uint8_t node;
    size_t input_words;
    size_t output_words;
} gsdc_gateway_node_t;

/* How a gateway's diagnosis block carries its code: one byte, one of the
 * type's codes, or a 16-bit number, high byte first. */
typedef enum {
    GSDC_DIAG_CODE_BYTE = 0,
    GSDC_DIAG_CODE_WORD
} gsdc_diag_code_t;

/* A type of a gateway's diagnosis: its value, the bytes of its blocks (the
 * header included), its code, and the codes a one-byte code may be (none
 * for a 16-bit number). */
typedef struct {
    uint8_t value;
    size_t len;
    gsdc_diag_code_t code;
    const uint16_t *codes;
    size_t codes_count;
} gsdc_gateway_diag_type_t;

/* Where a gateway's diagnosis block (the header being byte 0) holds the
 * type, the node and the code, and the types there are. */
typedef struct {
    size_t type_at;
    size_t node_at;
    size_t code_at;
    const gsdc_gateway_diag_type_t *types;
    size_t types_count;
} gsdc_gateway_diagnosis_t;

/* A gateway's nodes, as User_Prm_Data puts them in use: the place of the
 * number of nodes in use in the user_prm's params, then every node number,
 * the first first (the first node_count are in use, each one's words
 * following those of the nodes before it), and its diagnosis (NULL without
 * one). */
typedef struct {
    size_t node_count;
    const gsdc_gateway_node_t *nodes;
    size_t nodes_count;
    const gsdc_gateway_diagnosis_t *diagnosis;
} gsdc_dp_gateway_t;

/* A PROFIBUS-DP slave: its ident number, whether it takes Global_Control's
 * Freeze and Sync (Freeze_Mode_supp, Sync_Mode_supp), every Module of the
 * GSD, Max_Module, a gateway's node totals (NULL for a card whose
 * configuration is one module), User_Prm_Data, the bytes of its
 * device-related diagnosis block with the header (0 without one) and a
 * drive's card's block (NULL without one), its PKW codec, whether PZD1 from
 * the master is the control word and PZD1 to the master the status word,
 * the PZD words User_Prm_Data maps each way, and a gateway's nodes (NULL
 * for a drive's card). */
typedef struct {
    uint16_t ident_number;
    bool freeze_mode;
    bool sync_mode;
    const gsdc_dp_module_t *modules;
    size_t modules_count;
    size_t max_modules;
    gsdc_node_totals_t node_totals;
    gsdc_user_prm_t user_prm;
    size_t diagnosis_len;
    const gsdc_dp_diagnosis_t *diagnosis;
    gsdc_pkw_codec_t pkw;
    bool control_word;
    bool status_word;
    const gsdc_pzd_param_t *pzd_out;
    size_t pzd_out_count;
    const gsdc_pzd_param_t *pzd_in;
    size_t pzd_in_count;
    const gsdc_dp_gateway_t *gateway;
} gsdc_dp_device_t;

/* Whether the GSD allows `param` to hold `value`. */
static inline bool gsdc_dp_param_allows(const gsdc_dp_param_t *param, uint16_t value)
{
    bool allowed = (value >= param->min) && (value <= param->max);
    if (allowed && (param->values_count > 0U)) {
        size_t i;
        allowed = false;
        for (i = 0U; i < param->values_count; i++) {
            allowed = allowed || (param->values[i] == value);
        }
    }
    return allowed;
}

/* The parameter the GSD names `name`; NULL when it has none. */
static inline const gsdc_dp_param_t *gsdc_dp_param_find(const gsdc_user_prm_t *user_prm,
                                                        const char *name)
{
    const gsdc_dp_param_t *found = NULL;
    size_t i;
    for (i = 0U; (found == NULL) && (i < user_prm->params_count); i++) {
        const char *a = user_prm->params[i].name;
        const char *b = name;
        while ((*a != '\0') && (*a == *b)) {
            a++;
            b++;
        }
        if (*a == *b) {
            found = &user_prm->params[i];
        }
    }
    return found;
}

/* The bits of a Bit or BitArea, as a mask from bit 0. */
static inline uint16_t gsdc_dp_param_mask(const gsdc_dp_param_t *param)
{
    return (uint16_t)((1UL << (param->last_bit - param->first_bit + 1U)) - 1UL);
}

/* The value of `param` in User_Prm_Data (`len` bytes) into `value`:
 * GSDC_PRM_LENGTH when it does not fit, GSDC_PRM_NOT_ALLOWED when the GSD
 * does not allow it; `value` is written only when the result is GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_dp_param_read(const gsdc_dp_param_t *param,
                                                   const uint8_t *bytes, size_t len,
                                                   uint16_t *value)
{
    size_t size = 1U;
    gsdc_prm_result_t result = gsdc_prm_ok();
    if (param->data_type == GSDC_PRM_DATA_TYPE_UNSIGNED16) {
        size = 2U;
    }
    if ((param->offset > len) || (size > len - param->offset)) {
        result.fault = GSDC_PRM_LENGTH;
        result.expected = param->offset + size;
        result.found = len;
    } else {
        uint16_t found;
        if (size == 2U) {
            found = gsdc_u16be_get(&bytes[param->offset]);
        } else if (param->data_type == GSDC_PRM_DATA_TYPE_UNSIGNED8) {
            found = bytes[param->offset];
        } else {
            found = (uint16_t)((unsigned int)bytes[param->offset] >> param->first_bit);
            found = (uint16_t)(found & gsdc_dp_param_mask(param));
        }
        if (gsdc_dp_param_allows(param, found)) {
            *value = found;
        } else {
            result.fault = GSDC_PRM_NOT_ALLOWED;
            result.offset = param->offset;
            result.value = found;
        }
    }
    return result;
}

/* GSDC_PRM_OK when User_Prm_Data (`len` bytes) has the table's length and
 * every parameter a value the GSD allows; else the first fault, and
 * Chk_Prm answers Prm_Fault. */
static inline gsdc_prm_result_t gsdc_user_prm_check(const gsdc_user_prm_t *user_prm,
                                                    const uint8_t *bytes, size_t len)
{
    gsdc_prm_result_t result = gsdc_prm_check_len(len, user_prm->len);
    size_t i;
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < user_prm->params_count); i++) {
        uint16_t value;
        result = gsdc_dp_param_read(&user_prm->params[i], bytes, len, &value);
    }
    return result;
}

/* Whether the slave takes the configuration `config` (Chk_Cfg's `len`
 * bytes) with User_Prm_Data `user_prm` (`prm_len` bytes): at most
 * max_modules modules, each one's config bytes in turn; one at least, except
 * for a gateway, whose modules carry as many bytes as the nodes in use (none
 * for nodes without words). Its bytes of input and output go into
 * `input_len` and `output_len`, written only when it is taken. */
static inline bool gsdc_dp_check_config(const gsdc_dp_device_t *device,
                                        const uint8_t *user_prm, size_t prm_len,
                                        const uint8_t *config, size_t len, size_t *input_len,
                                        size_t *output_len)
{
    size_t at = 0U;
    size_t plugged = 0U;
    size_t input = 0U;
    size_t output = 0U;
    bool taken = true;
    while (taken && (at < len)) {
        const gsdc_dp_module_t *found = NULL;
        size_t m;
        for (m = 0U; (found == NULL) && (m < device->modules_count); m++) {
            const gsdc_dp_module_t *module = &device->modules[m];
            bool same = module->config_count <= len - at;
            size_t i;
            for (i = 0U; same && (i < module->config_count); i++) {
                same = config[at + i] == module->config[i];
            }
            if (same) {
                found = module;
            }
        }
        if (found == NULL) {
            taken = false;
        } else {
            at += found->config_count;
            input += found->input_len;
            output += found->output_len;
            plugged++;
        }
    }
    taken = taken && (plugged <= device->max_modules);
    if (device->node_totals == NULL) {
        taken = taken && (plugged >= 1U);
    } else if (taken) {
        size_t nodes_input;
        size_t nodes_output;
        taken = device->node_totals(user_prm, prm_len, &nodes_input, &nodes_output) &&
                (nodes_input == input) && (nodes_output == output);
    }
    if (taken) {
        *input_len = input;
        *output_len = output;
    }
    return taken;
}

/* A submodule: its subslot, ident number and bytes of IO data. */
typedef struct {
    uint16_t subslot;
    uint32_t ident;
    size_t input_len;
    size_t output_len;
} gsdc_pn_submodule_t;

/* How much of a record the controller writes: every entry (exactly len
 * bytes), or the first entries (at most len bytes; the others keep their
 * defaults). */
typedef enum {
    GSDC_RECORD_READING_WHOLE = 0,
    GSDC_RECORD_READING_PREFIX
} gsdc_record_reading_t;

/* A parameter record of a module's data submodule: its index, its bytes
 * (its entries', then its fail-safe values'), how much of it the controller
 * writes, its entries in record order, each one a place in a layout's group
 * of mappings, whose entry_allows checks it, each entry's value as the
 * GSDML gives it (DefaultValue: its default, or the value the module
 * fixes), which fills what a prefix leaves out, and whether the controller
 * may change each entry (the GSDML's Changeable: one that is not holds its
 * default); and the bytes of each value the settings record ends with after
 * its entries, one per output PZD item of the module (2, or 4 for a 32-bit
 * item), when the description has fail-safe values. */
typedef struct {
    uint16_t index;
    size_t len;
    gsdc_record_reading_t reading;
    gsdc_entry_allows_t allows;
    gsdc_entry_bytes_t entry_bytes;
    const size_t *entries;
    size_t entries_count;
    const uint16_t *defaults;
    size_t defaults_count;
    const bool *changeable;
    size_t changeable_count;
    const uint8_t *fail_safe;
    size_t fail_safe_count;
} gsdc_pn_record_t;

/* A module of the GSDML: its English name, ident number, the slots it may
 * be plugged into, its API (0, or PROFIdrive's 0x3A00), whether its
 * telegrams start with the PKW channel and its PZD words each way, the PZD
 * words (from 1) where a 32-bit value starts, high word first, the same
 * both ways (standard telegram 2's NSOLL_B and NIST_B at 2; NULL without),
 * PROFIdrive's module access point (NULL without one), its data submodule
 * and its records. */
typedef struct {
    const char *name;
    uint32_t ident;
    const uint16_t *slots;
    size_t slots_count;
    uint32_t api;
    bool pkw;
    size_t pzd_words;
    const size_t *double_words;
    size_t double_words_count;
    const gsdc_pn_submodule_t *access_point;
    gsdc_pn_submodule_t data;
    const gsdc_pn_record_t *records;
    size_t records_count;
} gsdc_pn_module_t;

/* A PZD word and the record entry whose value is the drive parameter it
 * carries: the word's number in the telegram (from 1, PZD1 following the
 * PKW channel), the record's index and the entry's place in it, from 0, in
 * the record of the plugged module. */
typedef struct {
    uint8_t word;
    uint16_t record;
    size_t entry;
} gsdc_pn_pzd_t;


/* A value of a record of the card's own: its English name, its first byte
 * in the record, its bytes (1, 2 or 4, high byte first; 0 for bits of the
 * byte at `offset`), the bits of a Bit or BitArea (0 and 7 for whole
 * bytes), its default, what it may hold (min to max, and one of `values`
 * when the GSDML lists them: NULL for every value of the range), and
 * whether the controller may change it (one that is not holds its
 * default). */
typedef struct {
    const char *name;
    size_t offset;
    size_t bytes;
    uint8_t first_bit;
    uint8_t last_bit;
    uint32_t default_value;
    uint32_t min;
    uint32_t max;
    const uint32_t *values;
    size_t values_count;
    bool changeable;
} gsdc_pn_record_value_t;

/* A parameter record of the card's own, of a device access point's
 * submodule or of a port: its index, its bytes (as far as its values
 * reach) and its values in the GSDML's order. */
typedef struct {
    uint16_t index;
    size_t len;
    const gsdc_pn_record_value_t *values;
    size_t values_count;
} gsdc_pn_submodule_record_t;

/* A device access point: its module ident number, its own submodule, its
 * ports (the interface is the device's), the modules it offers, by their
 * places in the device's modules, and the card's own records of its
 * submodule and of each of its ports. The firmware of each hardware or
 * firmware version of the card presents its own in slot 0. */
typedef struct {
    uint32_t ident;
    gsdc_pn_submodule_t submodule;
    const gsdc_pn_submodule_t *ports;
    size_t ports_count;
    const size_t *modules;
    size_t modules_count;
    const gsdc_pn_submodule_record_t *access_point_records;
    size_t access_point_records_count;
    const gsdc_pn_submodule_record_t *port_records;
    size_t port_records_count;
} gsdc_pn_dap_t;

/* A PROFIsafe module: its ident number, its submodule with the safety data
 * (the message trailer included), and that submodule's parameter records
 * besides the F-parameters (SEW's MOVI-C: record 8200), which the card's
 * PROFIsafe layer reads. */
typedef struct {
    uint32_t ident;
    gsdc_pn_submodule_t submodule;
    const gsdc_pn_submodule_record_t *records;
    size_t records_count;
} gsdc_pn_safety_module_t;

/* A PROFINET IO device: its identity and DNS_CompatibleName (the
 * NameOfStation an engineering tool proposes), the GSDML's device access
 * points in its order (those of one ident number present the same slot 0:
 * the device cannot tell which one a project used, and takes what any of
 * them offers, gsdc_pn_device_offers), the interface submodule, every
 * module of the GSDML, its PROFIsafe modules, its PKW codec,
 * whether PZD1 from the controller is the control word and PZD1 to the
 * controller the status word, and the PZD words the records map each
 * way. */
typedef struct {
    uint16_t vendor_id;
    uint16_t device_id;
    const char *dns_name;
    const gsdc_pn_dap_t *daps;
    size_t daps_count;
    gsdc_pn_submodule_t interface_submodule;
    const gsdc_pn_module_t *modules;
    size_t modules_count;
    const gsdc_pn_safety_module_t *safety_modules;
    size_t safety_modules_count;
    gsdc_pkw_codec_t pkw;
    bool control_word;
    bool status_word;
    const gsdc_pn_pzd_t *pzd_out;
    size_t pzd_out_count;
    const gsdc_pn_pzd_t *pzd_in;
    size_t pzd_in_count;
} gsdc_pn_device_t;

/* Whether a device presenting device access point ident `dap_ident` in slot
 * 0 takes the module at `place` in d->modules: whether a device access point
 * of that ident number offers it. */
static inline bool gsdc_pn_device_offers(const gsdc_pn_device_t *d, uint32_t dap_ident,
                                         size_t place)
{
    size_t i;
    size_t j;
    for (i = 0U; i < d->daps_count; i++) {
        const gsdc_pn_dap_t *dap = &d->daps[i];
        if (dap->ident != dap_ident) {
            continue;
        }
        for (j = 0U; j < dap->modules_count; j++) {
            if (dap->modules[j] == place) {
                return true;
            }
        }
    }
    return false;
}

/* The record `index` a device presenting device access point ident
 * `dap_ident` takes at its own submodule (`port` false) or at a port: the
 * first device access point of that ident number that has one (those of
 * one ident number give each index alike, gsdc's E162); NULL for none. */
static inline const gsdc_pn_submodule_record_t *gsdc_pn_device_own_record(
    const gsdc_pn_device_t *d, uint32_t dap_ident, bool port, uint16_t index)
{
    size_t i;
    size_t j;
    for (i = 0U; i < d->daps_count; i++) {
        const gsdc_pn_dap_t *dap = &d->daps[i];
        const gsdc_pn_submodule_record_t *records = dap->access_point_records;
        size_t count = dap->access_point_records_count;
        if (dap->ident != dap_ident) {
            continue;
        }
        if (port) {
            records = dap->port_records;
            count = dap->port_records_count;
        }
        for (j = 0U; j < count; j++) {
            if (records[j].index == index) {
                return &records[j];
            }
        }
    }
    return NULL;
}

/* The value `v` holds in a record of `len` bytes at `bytes`: GSDC_PRM_LENGTH
 * when its bytes are not all in it. */
static inline gsdc_prm_result_t gsdc_pn_record_value_get(const gsdc_pn_record_value_t *v,
                                                         const uint8_t *bytes, size_t len,
                                                         uint32_t *value)
{
    size_t whole = v->bytes;
    gsdc_prm_result_t result = gsdc_prm_ok();
    uint32_t number = 0U;
    size_t b;
    if (whole == 0U) {
        whole = 1U; /* bits of one byte */
    }
    if ((v->offset > len) || (whole > len - v->offset)) {
        return gsdc_prm_check_len(len, v->offset + whole);
    }
    for (b = 0U; b < whole; b++) {
        number = (number << 8) | bytes[v->offset + b];
    }
    if (v->bytes == 0U) {
        number = (number >> v->first_bit) & ((1U << (v->last_bit - v->first_bit + 1U)) - 1U);
    }
    *value = number;
    return result;
}

/* Whether the GSDML allows `value` for `v`. */
static inline bool gsdc_pn_record_value_allows(const gsdc_pn_record_value_t *v, uint32_t value)
{
    bool listed = (v->values_count == 0U);
    size_t i;
    for (i = 0U; i < v->values_count; i++) {
        listed = listed || (v->values[i] == value);
    }
    return (value >= v->min) && (value <= v->max) && listed &&
           (v->changeable || (value == v->default_value));
}

/* The values of a record the controller wrote (exactly `len` bytes) into
 * values[0..values_count), each one checked (one the controller may not
 * change must hold its default); `values` is written only when the result
 * is GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_pn_submodule_record_decode(
    const gsdc_pn_submodule_record_t *record, const uint8_t *bytes, size_t len, uint32_t *values)
{
    gsdc_prm_result_t result = gsdc_prm_check_len(len, record->len);
    size_t i;
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < record->values_count); i++) {
        const gsdc_pn_record_value_t *v = &record->values[i];
        uint32_t value = 0U;
        result = gsdc_pn_record_value_get(v, bytes, len, &value);
        if ((result.fault == GSDC_PRM_OK) && !gsdc_pn_record_value_allows(v, value)) {
            result.fault = GSDC_PRM_NOT_ALLOWED;
            result.offset = v->offset;
            result.value = value;
        }
    }
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < record->values_count); i++) {
        (void)gsdc_pn_record_value_get(&record->values[i], bytes, len, &values[i]);
    }
    return result;
}

/* The entries' values of a record the controller wrote (`len` bytes) into
 * the first entries_count of `values`, each one checked (an entry the
 * module fixes must hold its default); `values` is written only when the
 * result is GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_pn_record_decode(const gsdc_pn_record_t *record,
                                                      const uint8_t *bytes, size_t len,
                                                      uint16_t *values)
{
    gsdc_prm_result_t result = gsdc_prm_check_prefix_len(len, record->len);
    size_t at = 0U;
    size_t i;
    if (record->reading == GSDC_RECORD_READING_WHOLE) {
        result = gsdc_prm_check_len(len, record->len);
    }
    /* A prefix is of a PZD record's entries, two bytes each: every entry
     * it holds ends within `len`. */
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < record->entries_count); i++) {
        size_t size = record->entry_bytes(record->entries[i]);
        if (at + size <= len) {
            uint16_t value = gsdc_entry_get(&bytes[at], size);
            bool fixed = (i < record->changeable_count) && !record->changeable[i];
            if (!record->allows(record->entries[i], value) ||
                (fixed && ((i >= record->defaults_count) || (record->defaults[i] != value)))) {
                result.fault = GSDC_PRM_NOT_ALLOWED;
                result.offset = at;
                result.value = value;
            }
        }
        at += size;
    }
    at = 0U;
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < record->defaults_count); i++) {
        size_t size = 2U;
        if (i < record->entries_count) {
            size = record->entry_bytes(record->entries[i]);
        }
        values[i] = record->defaults[i];
        if (at + size <= len) {
            values[i] = gsdc_entry_get(&bytes[at], size);
        }
        at += size;
    }
    return result;
}

/* Decodes the fail-safe values a record the controller wrote, `len` bytes,
 * ends with, high byte first, into values[0..fail_safe_count); any value of
 * its width is allowed. `values` is written only when the result is
 * GSDC_PRM_OK: the record is exactly the record's length, and its entries
 * and values fit in it (else the table disagrees with itself). */
static inline gsdc_prm_result_t gsdc_pn_record_fail_safe(const gsdc_pn_record_t *record,
                                                         const uint8_t *bytes, size_t len,
                                                         uint32_t *values)
{
    gsdc_prm_result_t result = gsdc_prm_check_len(len, record->len);
    size_t start = 0U;
    size_t end;
    size_t i;
    for (i = 0U; i < record->entries_count; i++) {
        start += record->entry_bytes(record->entries[i]);
    }
    end = start;
    for (i = 0U; i < record->fail_safe_count; i++) {
        end += record->fail_safe[i];
    }
    if ((result.fault == GSDC_PRM_OK) && (end > len)) {
        result = gsdc_prm_check_len(len, end);
    }
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < record->fail_safe_count); i++) {
        uint32_t value = 0U;
        size_t b;
        for (b = 0U; b < record->fail_safe[i]; b++) {
            value = (value << 8) | bytes[start + b];
        }
        values[i] = value;
        start += record->fail_safe[i];
    }
    return result;
}

/* ------------------------------------------------------------------------
 * How a drive numbers its parameters: a layout's <prefix>_numbering() reads a
 * name as the manual writes it (F0-08) into the address the telegrams carry
 * (0xF008), and writes an address back as a name, as gsdc reads and writes
 * the description's names. A name is <prefix><group><separator><index>, the
 * prefix standing for a base added to the group. */

/* A prefix and the base it stands for. */
typedef struct {
    const char *prefix;
    uint8_t base;
} gsdc_numbering_prefix_t;

/* The prefix the description writes `address` with. */
typedef struct {
    uint16_t address;
    const char *prefix;
} gsdc_written_prefix_t;

/* How the group (with its base) and the index make an address: the group
 * the high byte and the index the low byte (F0-12 = 0xF00C), or the group
 * times 10 to the index's digits plus the index (P10.05 = 1005). */
typedef enum {
    GSDC_ADDRESS_SCHEME_BYTES = 0,
    GSDC_ADDRESS_SCHEME_DECIMAL
} gsdc_address_scheme_t;

/* A drive's numbering: the separator between the group and the index ("-",
 * "." or "" when exact_digits fixes where the group ends), the group's
 * radix (16: F0..FF, 10: P43), every prefix with its base (the longest
 * first), the scheme, the digits of a group and of an index as names are
 * written back, whether a name has exactly these digits (otherwise fewer are
 * read too, at most three), and the addresses the description writes with
 * a prefix other than the one gsdc_numbering_name would choose. */
typedef struct {
    const char *separator;
    uint8_t group_radix;
    const gsdc_numbering_prefix_t *prefixes;
    size_t prefixes_count;
    gsdc_address_scheme_t scheme;
    uint8_t group_digits;
    uint8_t index_digits;
    bool exact_digits;
    const gsdc_written_prefix_t *written;
    size_t written_count;
} gsdc_numbering_t;

/* `radix` to the power `digits`. */
static inline uint32_t gsdc_numbering_power(uint32_t radix, uint8_t digits)
{
    uint32_t value = 1U;
    uint8_t i;
    for (i = 0U; i < digits; i++) {
        value *= radix;
    }
    return value;
}

/* How many groups a prefix has, and how many indexes a group has. */
static inline uint32_t gsdc_numbering_groups(const gsdc_numbering_t *n)
{
    return gsdc_numbering_power(n->group_radix, n->group_digits);
}

static inline uint32_t gsdc_numbering_indexes(const gsdc_numbering_t *n)
{
    uint32_t indexes = 0x100U;
    uint32_t written = gsdc_numbering_power(10U, n->index_digits);
    if (n->scheme == GSDC_ADDRESS_SCHEME_DECIMAL) {
        indexes = written;
    }
    if (n->exact_digits && (written < indexes)) {
        indexes = written;
    }
    return indexes;
}

/* The value of the digits `text[0..len)` in `radix` (upper- or lower-case
 * hex), when there are 1 to `most` of them. */
static inline bool gsdc_numbering_digits(const char *text, size_t len, uint32_t radix,
                                         size_t most, uint32_t *value)
{
    bool ok = (len >= 1U) && (len <= most);
    uint32_t found = 0U;
    size_t i;
    for (i = 0U; ok && (i < len); i++) {
        char c = text[i];
        uint32_t digit = radix;
        if ((c >= '0') && (c <= '9')) {
            digit = (uint32_t)(c - '0');
        } else if ((c >= 'A') && (c <= 'F')) {
            digit = (uint32_t)(c - 'A') + 10U;
        } else if ((c >= 'a') && (c <= 'f')) {
            digit = (uint32_t)(c - 'a') + 10U;
        }
        ok = digit < radix;
        found = (found * radix) + digit;
    }
    if (ok) {
        *value = found;
    }
    return ok;
}

static inline size_t gsdc_numbering_strlen(const char *text)
{
    size_t len = 0U;
    while (text[len] != '\0') {
        len++;
    }
    return len;
}

/* Appends `text` to `name` (`size` bytes, `*len` used); false when it does
 * not fit with the terminating NUL. */
static inline bool gsdc_numbering_put(char *name, size_t size, size_t *len, const char *text)
{
    size_t add = gsdc_numbering_strlen(text);
    bool fits = (add < size) && (*len < size - add);
    size_t i;
    for (i = 0U; fits && (i < add); i++) {
        name[*len + i] = text[i];
    }
    if (fits) {
        *len += add;
        name[*len] = '\0';
    }
    return fits;
}

/* Appends `value` in `radix` (upper-case hex), with leading zeros to
 * `digits` digits. */
static inline bool gsdc_numbering_put_number(char *name, size_t size, size_t *len,
                                             uint32_t value, uint32_t radix, uint8_t digits)
{
    char written[12];
    char reversed[12];
    size_t count = 0U;
    size_t i;
    uint32_t rest = value;
    while (((rest > 0U) || (count < digits)) && (count < (sizeof written) - 1U)) {
        uint32_t digit = rest % radix;
        if (digit < 10U) {
            reversed[count] = (char)('0' + (int)digit);
        } else {
            reversed[count] = (char)('A' + (int)(digit - 10U));
        }
        rest /= radix;
        count++;
    }
    for (i = 0U; i < count; i++) {
        written[i] = reversed[count - 1U - i];
    }
    written[count] = '\0';
    return (rest == 0U) && gsdc_numbering_put(name, size, len, written);
}

/* The prefix, group and index written as a name into `name` (`size`
 * bytes, NUL-terminated); false when it does not fit. */
static inline bool gsdc_numbering_compose(const gsdc_numbering_t *n, const char *prefix,
                                          uint32_t group, uint32_t index, char *name, size_t size)
{
    size_t len = 0U;
    if (size > 0U) {
        name[0] = '\0';
    }
    return gsdc_numbering_put(name, size, &len, prefix) &&
           gsdc_numbering_put_number(name, size, &len, group, n->group_radix, n->group_digits) &&
           gsdc_numbering_put(name, size, &len, n->separator) &&
           gsdc_numbering_put_number(name, size, &len, index, 10U, n->index_digits);
}

/* The address of the parameter the manual names `name` (NUL-terminated)
 * into `address`; false when the name is not one of this numbering (written
 * otherwise than the description writes names, beyond the address space):
 * `address` is written only when it is. */
static inline bool gsdc_numbering_address(const gsdc_numbering_t *n, const char *name,
                                          uint16_t *address)
{
    const gsdc_numbering_prefix_t *prefix = NULL;
    size_t name_len = gsdc_numbering_strlen(name);
    size_t separator_len = gsdc_numbering_strlen(n->separator);
    size_t at = 0U;
    size_t i;
    bool ok;
    uint32_t group = 0U;
    uint32_t index = 0U;
    uint32_t sum;
    uint32_t found = 0U;
    size_t group_len = 0U;
    size_t group_most = 3U;
    for (i = 0U; (prefix == NULL) && (i < n->prefixes_count); i++) {
        size_t len = gsdc_numbering_strlen(n->prefixes[i].prefix);
        size_t j;
        bool same = len <= name_len;
        for (j = 0U; same && (j < len); j++) {
            same = name[j] == n->prefixes[i].prefix[j];
        }
        if (same) {
            prefix = &n->prefixes[i];
            at = len;
        }
    }
    ok = prefix != NULL;
    if (ok && n->exact_digits && (separator_len == 0U)) {
        group_len = n->group_digits;
        ok = (name_len - at) == ((size_t)n->group_digits + n->index_digits);
    } else if (ok) {
        /* The group ends at the first separator. */
        ok = false;
        for (i = at; !ok && (i + separator_len <= name_len); i++) {
            size_t j;
            bool same = true;
            for (j = 0U; same && (j < separator_len); j++) {
                same = name[i + j] == n->separator[j];
            }
            if (same) {
                ok = true;
                group_len = i - at;
            }
        }
    }
    /* A group has the numbering's digits when it fixes them, else 1 to 3;
     * the separator follows it unless the digits alone end it. */
    if (n->exact_digits) {
        group_most = n->group_digits;
    }
    ok = ok && gsdc_numbering_digits(&name[at], group_len, n->group_radix, group_most, &group) &&
         (group < gsdc_numbering_groups(n));
    at += group_len;
    if (!n->exact_digits || (separator_len != 0U)) {
        at += separator_len;
    }
    ok = ok && gsdc_numbering_digits(&name[at], name_len - at, 10U, 3U, &index) &&
         (index < gsdc_numbering_indexes(n));
    if (ok) {
        sum = (uint32_t)prefix->base + group;
        if (n->scheme == GSDC_ADDRESS_SCHEME_BYTES) {
            ok = sum <= 0xFFU;
            found = (sum << 8) | index;
        } else {
            found = (sum * gsdc_numbering_power(10U, n->index_digits)) + index;
        }
        ok = ok && (found <= 0xFFFFU);
    }
    if (ok && n->exact_digits) {
        /* A name is read only as it is written back. */
        char canonical[32];
        ok = gsdc_numbering_compose(n, prefix->prefix, group, index, canonical,
                                    sizeof canonical);
        for (i = 0U; ok && (i <= name_len); i++) {
            ok = canonical[i] == name[i];
        }
    }
    if (ok) {
        *address = (uint16_t)found;
    }
    return ok;
}

/* The name the manual gives the parameter at `address`, into `name`
 * (`size` bytes, NUL-terminated): with the prefix the description writes
 * it with, else the one of the highest base that covers it (of two of one
 * base, the first of the prefixes); false when no prefix covers it or the
 * name does not fit. */
static inline bool gsdc_numbering_name(const gsdc_numbering_t *n, uint16_t address, char *name,
                                       size_t size)
{
    uint32_t sum = (uint32_t)address >> 8;
    uint32_t index = (uint32_t)address & 0xFFU;
    const char *written = NULL;
    const gsdc_numbering_prefix_t *best = NULL;
    bool chosen = false;
    size_t i;
    if (n->scheme == GSDC_ADDRESS_SCHEME_DECIMAL) {
        sum = (uint32_t)address / gsdc_numbering_power(10U, n->index_digits);
        index = (uint32_t)address % gsdc_numbering_power(10U, n->index_digits);
    }
    for (i = 0U; i < n->written_count; i++) {
        if (n->written[i].address == address) {
            written = n->written[i].prefix;
        }
    }
    for (i = 0U; !chosen && (i < n->prefixes_count); i++) {
        const gsdc_numbering_prefix_t *p = &n->prefixes[i];
        bool covers = ((uint32_t)p->base <= sum) &&
                      ((sum - (uint32_t)p->base) < gsdc_numbering_groups(n));
        if (covers && (written != NULL)) {
            size_t j = 0U;
            while ((p->prefix[j] != '\0') && (p->prefix[j] == written[j])) {
                j++;
            }
            chosen = p->prefix[j] == written[j];
        }
        if (covers && (chosen || (best == NULL) || (p->base > best->base))) {
            best = p;
        }
    }
    return (index < gsdc_numbering_indexes(n)) && (best != NULL) &&
           gsdc_numbering_compose(n, best->prefix, sum - (uint32_t)best->base, index, name, size);
}

#ifdef __cplusplus
}
#endif

#endif /* GSDC_SUPPORT_H */
