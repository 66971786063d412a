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
    /* The value at byte `offset` is `value`, which its mapping does not allow. */
    GSDC_PRM_NOT_ALLOWED
} gsdc_prm_fault_t;

/* What decoding a parameter telegram or record found: the fault, and the
 * fields that fault names (the others are 0). */
typedef struct {
    gsdc_prm_fault_t fault;
    size_t expected;
    size_t found;
    size_t offset;
    uint16_t value;
} gsdc_prm_result_t;

/* Whether entry `index` (0 = the first) of a group of mappings may hold
 * `value`: a layout's <group>_entry_allows. */
typedef bool (*gsdc_entry_allows_t)(size_t index, uint16_t value);

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

/* Checks `count` Unsigned16 values from byte `offset` of `bytes` (`len`
 * bytes long), each with `allows`: GSDC_PRM_LENGTH when they do not fit in
 * `len` bytes, GSDC_PRM_NOT_ALLOWED for the first value `allows` refuses,
 * else GSDC_PRM_OK. */
static inline gsdc_prm_result_t gsdc_prm_check_values(const uint8_t *bytes, size_t len,
                                                      size_t offset, size_t count,
                                                      gsdc_entry_allows_t allows)
{
    gsdc_prm_result_t result = gsdc_prm_ok();
    size_t i;
    if ((offset > len) || (count > ((len - offset) / 2U))) {
        result.fault = GSDC_PRM_LENGTH;
        result.expected = offset + (2U * count);
        result.found = len;
    }
    for (i = 0U; (result.fault == GSDC_PRM_OK) && (i < count); i++) {
        size_t at = offset + (2U * i);
        uint16_t value = gsdc_u16be_get(&bytes[at]);
        if (!allows(i, value)) {
            result.fault = GSDC_PRM_NOT_ALLOWED;
            result.offset = at;
            result.value = value;
        }
    }
    return result;
}

/* Copies `count` Unsigned16 values from byte `offset` of `bytes` into
 * `values`; gsdc_prm_check_values has found them there. */
static inline void gsdc_prm_get_values(const uint8_t *bytes, size_t offset, size_t count,
                                       uint16_t *values)
{
    size_t i;
    for (i = 0U; i < count; i++) {
        values[i] = gsdc_word_get(&bytes[offset], i);
    }
}

/* gsdc_prm_check_values, then, when the result is GSDC_PRM_OK,
 * gsdc_prm_get_values: `values` is written only then. */
static inline gsdc_prm_result_t gsdc_prm_read_values(const uint8_t *bytes, size_t len,
                                                     size_t offset, size_t count,
                                                     gsdc_entry_allows_t allows,
                                                     uint16_t *values)
{
    gsdc_prm_result_t result = gsdc_prm_check_values(bytes, len, offset, count, allows);
    if (result.fault == GSDC_PRM_OK) {
        gsdc_prm_get_values(bytes, offset, count, values);
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
    /* A request command the manual does not define. */
    GSDC_PKW_BAD_COMMAND,
    /* A response code the manual does not define (PKE, IND, PWE). */
    GSDC_PKW_BAD_RESPONSE,
    /* "Cannot execute" with an error code other than 1 to 4 (PKE, IND, PWE). */
    GSDC_PKW_BAD_ERROR_CODE,
    /* A read whose count is not 1 (station, command, address, value). */
    GSDC_PKW_BAD_READ_COUNT
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

#ifdef __cplusplus
}
#endif

#endif /* GSDC_SUPPORT_H */
