/* The device tables of one C layout, dumped in the lines of
 * tests/firmware/device_files.rs, which reads the same facts from the GSD
 * and the GSDML: tests/device_tables_c.rs compiles this file once per
 * layout and compares. Generic: the layout is named by the macros
 * LAYOUT_HEADER, DP_DEVICE and PN_DEVICE (each table's function, left
 * undefined when the layout has none). Besides the dump, it uses the
 * support functions as a slave would: User_Prm_Data of the defaults passes
 * gsdc_user_prm_check, every parameter is found by its name, and a card of
 * one module takes each module's config bytes. A failure prints FAILED and
 * exits 1. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include LAYOUT_HEADER

static void fail(const char *what)
{
    printf("FAILED: %s\n", what);
    exit(1);
}

/* As Rust's {:?} prints an ASCII or UTF-8 name. */
static void print_name(const char *name)
{
    putchar('"');
    for (; *name != '\0'; name++) {
        if ((*name == '"') || (*name == '\\')) {
            putchar('\\');
        }
        putchar(*name);
    }
    putchar('"');
}

#ifdef DP_DEVICE
static void print_hex(const uint8_t *bytes, size_t count)
{
    size_t i;
    for (i = 0U; i < count; i++) {
        printf("%s%02X", (i == 0U) ? "" : " ", (unsigned int)bytes[i]);
    }
}

/* `0-5`, `0,2,7`: the values the parameter allows, as runs. */
static void print_allowed(const gsdc_dp_param_t *param)
{
    unsigned long v = 0UL;
    bool first = true;
    while (v <= 0xFFFFUL) {
        if (gsdc_dp_param_allows(param, (uint16_t)v)) {
            unsigned long last = v;
            while ((last < 0xFFFFUL) && gsdc_dp_param_allows(param, (uint16_t)(last + 1UL))) {
                last++;
            }
            if (!first) {
                putchar(',');
            }
            if (last == v) {
                printf("%lu", v);
            } else {
                printf("%lu-%lu", v, last);
            }
            first = false;
            v = last + 1UL;
        } else {
            v++;
        }
    }
}

static const char *data_type_name(gsdc_prm_data_type_t type)
{
    const char *name = "BitArea";
    if (type == GSDC_PRM_DATA_TYPE_UNSIGNED8) {
        name = "Unsigned8";
    } else if (type == GSDC_PRM_DATA_TYPE_UNSIGNED16) {
        name = "Unsigned16";
    } else if (type == GSDC_PRM_DATA_TYPE_BIT) {
        name = "Bit";
    }
    return name;
}

/* The parameter's default written into `bytes`, as a master would. */
static void put_default(const gsdc_dp_param_t *p, uint8_t *bytes)
{
    if (p->data_type == GSDC_PRM_DATA_TYPE_UNSIGNED16) {
        gsdc_u16be_put(&bytes[p->offset], p->default_value);
    } else if (p->data_type == GSDC_PRM_DATA_TYPE_UNSIGNED8) {
        bytes[p->offset] = (uint8_t)p->default_value;
    } else {
        bytes[p->offset] = (uint8_t)(bytes[p->offset] | (p->default_value << p->first_bit));
    }
}

static void dump_dp(const gsdc_dp_device_t *d)
{
    uint8_t user_prm[256] = {0U};
    size_t i;
    printf("ident 0x%04X\n", (unsigned int)d->ident_number);
    for (i = 0U; i < d->modules_count; i++) {
        const gsdc_dp_module_t *m = &d->modules[i];
        printf("module ");
        print_name(m->name);
        printf(" config ");
        print_hex(m->config, m->config_count);
        printf(" in %lu out %lu pkw %d pzd %lu\n", (unsigned long)m->input_len,
               (unsigned long)m->output_len, m->pkw ? 1 : 0, (unsigned long)m->pzd_words);
    }
    printf("max_modules %lu\n", (unsigned long)d->max_modules);
    printf("user_prm %lu dpv1 ", (unsigned long)d->user_prm.len);
    if (d->user_prm.dpv1_status == NULL) {
        printf("none");
    } else {
        print_hex(d->user_prm.dpv1_status, d->user_prm.dpv1_status_count);
    }
    printf("\n");
    for (i = 0U; i < d->user_prm.params_count; i++) {
        const gsdc_dp_param_t *p = &d->user_prm.params[i];
        printf("param ");
        print_name(p->name);
        printf(" offset %lu %s bits %u-%u default %u allowed ", (unsigned long)p->offset,
               data_type_name(p->data_type), (unsigned int)p->first_bit,
               (unsigned int)p->last_bit, (unsigned int)p->default_value);
        print_allowed(p);
        printf("\n");
        if (gsdc_dp_param_find(&d->user_prm, p->name) != p) {
            fail("a parameter is not found by its name");
        }
        put_default(p, user_prm);
    }
    printf("diagnosis %lu\n", (unsigned long)d->diagnosis_len);
    printf("global_control freeze %d sync %d\n", d->freeze_mode ? 1 : 0, d->sync_mode ? 1 : 0);
    for (i = 0U; i < d->user_prm.dpv1_status_count; i++) {
        user_prm[i] = d->user_prm.dpv1_status[i];
    }
    if ((d->user_prm.len > sizeof user_prm) ||
        (gsdc_user_prm_check(&d->user_prm, user_prm, d->user_prm.len).fault != GSDC_PRM_OK)) {
        fail("User_Prm_Data of the defaults is refused");
    }
    for (i = 0U; (d->node_totals == NULL) && (i < d->modules_count); i++) {
        const gsdc_dp_module_t *m = &d->modules[i];
        size_t input = 0U;
        size_t output = 0U;
        if (!gsdc_dp_check_config(d, user_prm, d->user_prm.len, m->config, m->config_count,
                                  &input, &output) ||
            (input != m->input_len) || (output != m->output_len)) {
            fail("a module's config bytes are refused");
        }
    }
}

/* A drive's card's diagnosis areas, in their own section. */
static void dump_dp_diagnosis(const gsdc_dp_diagnosis_t *d)
{
    size_t i;
    size_t j;
    if (gsdc_dp_diagnosis_header(d) != d->len) {
        fail("the block's header is not its length");
    }
    for (i = 0U; i < d->areas_count; i++) {
        const gsdc_dp_diag_area_t *a = &d->areas[i];
        printf("diag_area %u-%u values", (unsigned int)a->first_bit, (unsigned int)a->last_bit);
        for (j = 0U; j < a->values_count; j++) {
            printf("%s%u", (j == 0U) ? " " : ",", (unsigned int)a->values[j]);
        }
        printf("\n");
    }
}
#endif

#ifdef PN_DEVICE
static void print_submodule(const gsdc_pn_submodule_t *s)
{
    printf("submodule %u %lu in %lu out %lu\n", (unsigned int)s->subslot,
           (unsigned long)s->ident, (unsigned long)s->input_len, (unsigned long)s->output_len);
}

/* The byte offsets of a module's 32-bit values (PZD word `w` after the PKW
 * channel), the same both ways: nothing without any. */
static void print_double_words(const gsdc_pn_module_t *m)
{
    size_t way;
    size_t j;
    size_t pkw_words = m->pkw ? 4U : 0U;
    if (m->double_words_count == 0U) {
        return;
    }
    printf("u32");
    for (way = 0U; way < 2U; way++) {
        printf(way == 0U ? " in" : " out");
        for (j = 0U; j < m->double_words_count; j++) {
            printf(" %lu", (unsigned long)(2U * (pkw_words + m->double_words[j] - 1U)));
        }
    }
    printf("\n");
}

static void dump_record(const gsdc_pn_record_t *r)
{
    uint8_t bytes[2048];
    uint16_t values[256];
    uint32_t fail_safe[256];
    size_t len = 0U;
    size_t i;
    if ((r->defaults_count > 256U) || (r->fail_safe_count > 256U)) {
        fail("a record longer than the test's buffer");
    }
    /* Each entry of its bytes, as the GSDML's Refs lay them out, then each
     * fail-safe value, 0 as the GSDML's default. */
    for (i = 0U; i < r->defaults_count; i++) {
        size_t size = r->entry_bytes(r->entries[i]);
        if (size == 1U) {
            bytes[len] = (uint8_t)r->defaults[i];
        } else {
            gsdc_u16be_put(&bytes[len], r->defaults[i]);
        }
        len += size;
    }
    for (i = 0U; i < r->fail_safe_count; i++) {
        memset(&bytes[len], 0, r->fail_safe[i]);
        len += r->fail_safe[i];
    }
    if ((gsdc_pn_record_decode(r, bytes, len, values).fault != GSDC_PRM_OK) ||
        (gsdc_pn_record_fail_safe(r, bytes, len, fail_safe).fault != GSDC_PRM_OK)) {
        fail("a record of the GSDML's defaults is refused");
    }
    printf("record %u len %lu bytes", (unsigned int)r->index, (unsigned long)r->len);
    for (i = 0U; i < r->entries_count; i++) {
        printf(" %lu", (unsigned long)r->entry_bytes(r->entries[i]));
    }
    for (i = 0U; i < r->fail_safe_count; i++) {
        printf(" %u", (unsigned int)r->fail_safe[i]);
    }
    printf(" reads");
    for (i = 0U; i < r->entries_count; i++) {
        printf(" %u", (unsigned int)values[i]);
    }
    for (i = 0U; i < r->fail_safe_count; i++) {
        printf(" %lu", (unsigned long)fail_safe[i]);
    }
    printf(" changeable");
    for (i = 0U; i < r->changeable_count; i++) {
        printf(" %d", r->changeable[i] ? 1 : 0);
    }
    for (i = 0U; i < r->fail_safe_count; i++) {
        printf(" 1");
    }
    printf("\n");
}

/* A record of the access point or a port, as device_files.rs reads it from
 * the GSDML: each value's place, default, range, listed values and whether
 * the controller may change it; and the record of its defaults decoded. */
static void dump_own_record(const char *what, const gsdc_pn_submodule_record_t *r)
{
    uint8_t bytes[64] = {0U};
    uint32_t values[16];
    size_t i;
    size_t j;
    if ((r->len > sizeof bytes) || (r->values_count > 16U)) {
        fail("a record longer than the test's buffer");
    }
    printf("%s %u len %lu", what, (unsigned int)r->index, (unsigned long)r->len);
    for (i = 0U; i < r->values_count; i++) {
        const gsdc_pn_record_value_t *v = &r->values[i];
        printf(" | %lu %lu %u-%u default %lu range %lu..%lu values", (unsigned long)v->offset,
               (unsigned long)v->bytes, (unsigned int)v->first_bit, (unsigned int)v->last_bit,
               (unsigned long)v->default_value, (unsigned long)v->min, (unsigned long)v->max);
        for (j = 0U; j < v->values_count; j++) {
            printf(" %lu", (unsigned long)v->values[j]);
        }
        printf(" changeable %d", v->changeable ? 1 : 0);
        /* Its default, placed in the record of defaults. */
        for (j = 0U; j < v->bytes; j++) {
            bytes[v->offset + j] = (uint8_t)(v->default_value >> (8U * (v->bytes - 1U - j)));
        }
        if (v->bytes == 0U) {
            bytes[v->offset] |= (uint8_t)(v->default_value << v->first_bit);
        }
    }
    printf("\n");
    if (gsdc_pn_submodule_record_decode(r, bytes, r->len, values).fault != GSDC_PRM_OK) {
        fail("a record of the GSDML's defaults is refused");
    }
    for (i = 0U; i < r->values_count; i++) {
        if (values[i] != r->values[i].default_value) {
            fail("a record of the GSDML's defaults decodes to other values");
        }
    }
}

/* The record of each index of `records` a device presenting DAP ident
 * `ident` takes: `takes dap_record 8200 len 1`. */
static void dump_taken_records(const gsdc_pn_device_t *d, uint32_t ident, bool port,
                               const gsdc_pn_submodule_record_t *records, size_t count)
{
    size_t i;
    for (i = 0U; i < count; i++) {
        const gsdc_pn_submodule_record_t *taken =
            gsdc_pn_device_own_record(d, ident, port, records[i].index);
        if (taken == NULL) {
            fail("a record of a DAP of the ident number is not taken");
        }
        printf("takes %s %u len %lu\n", port ? "port_record" : "dap_record",
               (unsigned int)taken->index, (unsigned long)taken->len);
    }
}

/* A DAP's records of its own submodule and of its ports, then the record of
 * each index a DAP of its ident number has that a device presenting it
 * takes. */
static void dump_own_records(const gsdc_pn_device_t *d, const gsdc_pn_dap_t *dap)
{
    size_t i;
    for (i = 0U; i < dap->access_point_records_count; i++) {
        dump_own_record("dap_record", &dap->access_point_records[i]);
    }
    for (i = 0U; i < dap->port_records_count; i++) {
        dump_own_record("port_record", &dap->port_records[i]);
    }
    for (i = 0U; i < d->daps_count; i++) {
        const gsdc_pn_dap_t *other = &d->daps[i];
        if (other->ident != dap->ident) {
            continue;
        }
        dump_taken_records(d, dap->ident, false, other->access_point_records,
                           other->access_point_records_count);
        dump_taken_records(d, dap->ident, true, other->port_records, other->port_records_count);
    }
}

static void dump_pn(const gsdc_pn_device_t *d)
{
    size_t i;
    size_t j;
    printf("vendor %u device %u\n", (unsigned int)d->vendor_id, (unsigned int)d->device_id);
    printf("name %s\n", d->dns_name);
    for (i = 0U; i < d->daps_count; i++) {
        const gsdc_pn_dap_t *dap = &d->daps[i];
        printf("dap %lu submodule %u %lu", (unsigned long)dap->ident,
               (unsigned int)dap->submodule.subslot, (unsigned long)dap->submodule.ident);
        for (j = 0U; j < dap->ports_count; j++) {
            printf(" port %u %lu", (unsigned int)dap->ports[j].subslot,
                   (unsigned long)dap->ports[j].ident);
        }
        printf(" modules");
        for (j = 0U; j < dap->modules_count; j++) {
            printf(" %lu", (unsigned long)d->modules[dap->modules[j]].ident);
        }
        printf(" takes");
        for (j = 0U; j < d->modules_count; j++) {
            if (gsdc_pn_device_offers(d, dap->ident, j)) {
                printf(" %lu", (unsigned long)d->modules[j].ident);
            }
        }
        printf("\n");
        dump_own_records(d, dap);
    }
    printf("interface %u %lu\n", (unsigned int)d->interface_submodule.subslot,
           (unsigned long)d->interface_submodule.ident);
    for (i = 0U; i < d->modules_count; i++) {
        const gsdc_pn_module_t *m = &d->modules[i];
        printf("module ");
        print_name(m->name);
        printf(" ident %lu slots", (unsigned long)m->ident);
        for (j = 0U; j < m->slots_count; j++) {
            printf(" %u", (unsigned int)m->slots[j]);
        }
        printf(" api %lu\n", (unsigned long)m->api);
        if (m->access_point != NULL) {
            print_submodule(m->access_point);
        }
        print_submodule(&m->data);
        print_double_words(m);
        for (j = 0U; j < m->records_count; j++) {
            dump_record(&m->records[j]);
        }
    }
    for (i = 0U; i < d->safety_modules_count; i++) {
        const gsdc_pn_safety_module_t *m = &d->safety_modules[i];
        printf("safety_module %lu submodule %u %lu in %lu out %lu\n", (unsigned long)m->ident,
               (unsigned int)m->submodule.subslot, (unsigned long)m->submodule.ident,
               (unsigned long)m->submodule.input_len, (unsigned long)m->submodule.output_len);
        for (j = 0U; j < m->records_count; j++) {
            dump_own_record("safety_record", &m->records[j]);
        }
    }
}
#endif

#ifdef NUMBERING
/* Every address the numbering names, with its name, each name read back
 * to its address; then each of the names gsdc's test gives in argv, with
 * the address it reads (or "none"). */
static void dump_numbering(const gsdc_numbering_t *n, int argc, char **argv)
{
    uint32_t address;
    int i;
    for (address = 0U; address <= 0xFFFFU; address++) {
        char name[32];
        uint16_t back = 0U;
        if (gsdc_numbering_name(n, (uint16_t)address, name, sizeof name)) {
            printf("%04X %s\n", (unsigned int)address, name);
            if (!gsdc_numbering_address(n, name, &back) || (back != address)) {
                fail("a name is not read back to its address");
            }
        }
    }
    for (i = 1; i < argc; i++) {
        uint16_t read = 0U;
        if (gsdc_numbering_address(n, argv[i], &read)) {
            printf("read \"%s\" %04X\n", argv[i], (unsigned int)read);
        } else {
            printf("read \"%s\" none\n", argv[i]);
        }
    }
}
#endif

int main(int argc, char **argv)
{
#ifdef DP_DEVICE
    printf("[dp]\n");
    dump_dp(DP_DEVICE());
    if (DP_DEVICE()->diagnosis != NULL) {
        printf("[dp_diagnosis]\n");
        dump_dp_diagnosis(DP_DEVICE()->diagnosis);
    }
#endif
#ifdef PN_DEVICE
    printf("[pn]\n");
    dump_pn(PN_DEVICE());
#endif
#ifdef NUMBERING
    printf("[numbering]\n");
    dump_numbering(NUMBERING(), argc, argv);
#else
    (void)argc;
    (void)argv;
#endif
    return 0;
}
