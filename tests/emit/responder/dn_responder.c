/* Group-2-only DeviceNet slave on top of the generated header (device_eds.h).
 * Everything device-specific comes from EDS_* macros; what is left here is
 * the DeviceNet protocol and the firmware's own choices, marked as such. */
#include "dn_responder.h"

#include <string.h>

#include "device_eds.h"

/* Firmware property, not an EDS fact: time attributes are kept in 8 ms ticks
 * and Set replies carry the value kept. The RightSight capture is consistent
 * with it (production inhibit 1 -> 8 ms, expected packet rate 250 -> 256 ms). */
#define DN_TICK_MS 8u
#define DN_EXPLICIT_BUFFER 48u /* largest explicit message body handled */

static const uint8_t vendor_id[] = EDS_VENDOR_ID_BYTES;
static const uint8_t device_type[] = EDS_DEVICE_TYPE_BYTES;
static const uint8_t product_code[] = EDS_PRODUCT_CODE_BYTES;
static const uint8_t revision[] = EDS_REVISION_BYTES;
static const uint8_t serial_number[] = EDS_SERIAL_NUMBER_BYTES;
static const uint8_t product_name[] = EDS_PRODUCT_NAME_BYTES;

typedef struct reply {
  uint8_t body[DN_EXPLICIT_BUFFER]; /* service code, then data */
  uint8_t len;
} reply;

static void put(reply *r, const uint8_t *bytes, unsigned n) {
  memcpy(r->body + r->len, bytes, n);
  r->len = (uint8_t)(r->len + n);
}
static void put_uint(reply *r, unsigned v) {
  const uint8_t b[2] = {(uint8_t)(v & 0xFFu), (uint8_t)(v >> 8)};
  put(r, b, 2);
}
static void error(reply *r, unsigned status) {
  r->body[0] = EDS_SERVICE_ERROR_RESPONSE;
  r->body[1] = (uint8_t)status;
  r->body[2] = EDS_NO_ADDITIONAL_CODE;
  r->len = 3;
}
static uint16_t round_to_tick(unsigned ms) {
  unsigned kept = (ms + DN_TICK_MS - 1u) / DN_TICK_MS * DN_TICK_MS;
  return (uint16_t)(kept > 0xFFFFu ? 0xFFFFu / DN_TICK_MS * DN_TICK_MS : kept);
}

/* The allocation bit that brings connection instance 1..4 into existence. */
static uint8_t instance_bits(unsigned inst) {
  static const uint8_t bits[5] = {0, EDS_ALLOCATE_EXPLICIT, EDS_ALLOCATE_POLL, EDS_ALLOCATE_STROBE,
                                  EDS_ALLOCATE_COS | EDS_ALLOCATE_CYCLIC};
  return inst <= 4u ? bits[inst] : 0u;
}

static void io_sizes(const dn_slave *s, unsigned inst, unsigned *produced, unsigned *consumed) {
  switch (inst) {
    case 1: *produced = *consumed = DN_EXPLICIT_BUFFER; break;
    case 2: *produced = EDS_POLL_PRODUCED_SIZE; *consumed = EDS_POLL_CONSUMED_SIZE; break;
    case 3: *produced = EDS_STROBE_PRODUCED_SIZE; *consumed = EDS_STROBE_CONSUMED_SIZE; break;
    default:
      if (s->allocated & EDS_ALLOCATE_CYCLIC) {
        *produced = EDS_CYCLIC_PRODUCED_SIZE; *consumed = EDS_CYCLIC_CONSUMED_SIZE;
      } else {
        *produced = EDS_COS_PRODUCED_SIZE; *consumed = EDS_COS_CONSUMED_SIZE;
      }
  }
}

static void identity_get(unsigned attr, reply *r) {
  switch (attr) {
    case 1: put(r, vendor_id, sizeof vendor_id); break;
    case 2: put(r, device_type, sizeof device_type); break;
    case 3: put(r, product_code, sizeof product_code); break;
    case 4: put(r, revision, sizeof revision); break;
    case 5: put_uint(r, 0); break; /* status word: runtime, nothing to report here */
    case 6: put(r, serial_number, sizeof serial_number); break;
    case 7: put(r, product_name, sizeof product_name); break;
    default: error(r, EDS_STATUS_ATTRIBUTE_NOT_SUPPORTED);
  }
}

/* Checks a Set value's length; reports and returns 0 when wrong. */
static int value_size_ok(unsigned have, unsigned want, reply *r) {
  if (have == want) return 1;
  error(r, have < want ? EDS_STATUS_NOT_ENOUGH_DATA : EDS_STATUS_TOO_MUCH_DATA);
  return 0;
}

static void connection_service(dn_slave *s, int set, unsigned inst, unsigned attr, const uint8_t *v, unsigned n,
                               reply *r) {
  unsigned produced = 0, consumed = 0;
  if ((s->allocated & instance_bits(inst)) == 0u) {
    error(r, EDS_STATUS_OBJECT_DOES_NOT_EXIST);
    return;
  }
  io_sizes(s, inst, &produced, &consumed);
  switch (attr) {
    case 7:
    case 8:
      if (set) error(r, EDS_STATUS_ATTRIBUTE_NOT_SETTABLE);
      else put_uint(r, attr == 7 ? produced : consumed);
      return;
    case 9:
      if (set && value_size_ok(n, 2, r)) s->expected_packet_rate[inst] = round_to_tick(v[0] | (v[1] << 8));
      if (r->len == 1) put_uint(r, s->expected_packet_rate[inst]);
      return;
    case 0x0C:
      if (!set) {
        put(r, &s->watchdog_action[inst], 1);
      } else if (value_size_ok(n, 1, r)) {
        /* 0 transition to timed out, 1 auto delete, 2 auto reset; 3 deferred delete is explicit only. */
        if (v[0] > 3u || (v[0] == 3u && inst != 1u)) error(r, EDS_STATUS_INVALID_ATTRIBUTE_VALUE);
        else s->watchdog_action[inst] = v[0];
      }
      return;
    case 0x11:
      if (inst == 1u) break; /* production inhibit is an I/O attribute */
      if (set && value_size_ok(n, 2, r)) s->production_inhibit[inst] = round_to_tick(v[0] | (v[1] << 8));
      if (r->len == 1) put_uint(r, s->production_inhibit[inst]);
      return;
    default:
      break;
  }
  error(r, EDS_STATUS_ATTRIBUTE_NOT_SUPPORTED);
}

/* Acknowledge Handler (0x2B), present when the device can produce COS/cyclic data. */
static void ack_handler_service(dn_slave *s, int set, unsigned attr, const uint8_t *v, unsigned n, reply *r) {
  if (attr == 1u) {
    if (set && value_size_ok(n, 2, r)) s->ack_timer = round_to_tick(v[0] | (v[1] << 8));
    if (r->len == 1) put_uint(r, s->ack_timer);
  } else if (attr == 2u) {
    if (!set) put(r, &s->ack_retry_limit, 1);
    else if (value_size_ok(n, 1, r)) s->ack_retry_limit = v[0];
  } else {
    error(r, EDS_STATUS_ATTRIBUTE_NOT_SUPPORTED);
  }
}

static void attribute_service(dn_slave *s, int set, const uint8_t *req, unsigned n, reply *r) {
  const unsigned cls = req[1], inst = req[2], attr = req[3];
  const uint8_t *value = req + 4;
  const unsigned value_len = n - 4u;
  if (cls == EDS_CLASS_IDENTITY && inst == 1u) {
    if (set) error(r, attr >= 1u && attr <= 7u ? EDS_STATUS_ATTRIBUTE_NOT_SETTABLE : EDS_STATUS_ATTRIBUTE_NOT_SUPPORTED);
    else identity_get(attr, r);
  } else if (cls == EDS_CLASS_DEVICENET && inst == 1u && !set && (attr == 1u || attr == 2u)) {
    const uint8_t v = attr == 1u ? s->mac : 0u; /* baud rate 0 = 125 kbit/s */
    put(r, &v, 1);
  } else if (cls == EDS_CLASS_DEVICENET && inst == 1u) {
    error(r, set ? EDS_STATUS_ATTRIBUTE_NOT_SETTABLE : EDS_STATUS_ATTRIBUTE_NOT_SUPPORTED);
  } else if (cls == EDS_CLASS_CONNECTION) {
    connection_service(s, set, inst, attr, value, value_len, r);
  } else if (cls == EDS_CLASS_ACK_HANDLER && inst == 1u && (EDS_COS_SUPPORTED || EDS_CYCLIC_SUPPORTED)) {
    ack_handler_service(s, set, attr, value, value_len, r);
  } else {
    error(r, EDS_STATUS_OBJECT_DOES_NOT_EXIST);
  }
}

static void allocation_service(dn_slave *s, unsigned service, const uint8_t *req, unsigned n, reply *r) {
  const unsigned choice = n > 3u ? req[3] : 0u;
  if (req[1] != EDS_CLASS_DEVICENET || req[2] != 1u) {
    error(r, EDS_STATUS_OBJECT_DOES_NOT_EXIST);
  } else if (n < (service == EDS_SERVICE_ALLOCATE ? 5u : 4u)) {
    error(r, EDS_STATUS_NOT_ENOUGH_DATA);
  } else if (service == EDS_SERVICE_RELEASE) {
    s->allocated = (uint8_t)(s->allocated & ~choice);
  } else if ((choice & ~EDS_ALLOCATION_CHOICE_MASK) != 0u ||
             ((choice | s->allocated) & (EDS_ALLOCATE_COS | EDS_ALLOCATE_CYCLIC)) ==
                 (EDS_ALLOCATE_COS | EDS_ALLOCATE_CYCLIC)) {
    error(r, EDS_STATUS_RESOURCE_UNAVAILABLE); /* a type the EDS does not offer, or COS with cyclic */
  } else if (s->allocated != 0u && req[4] != s->master_mac) {
    error(r, EDS_STATUS_OBJECT_STATE_CONFLICT); /* owned by another master */
  } else {
    s->allocated = (uint8_t)(s->allocated | choice);
    s->master_mac = req[4];
    r->body[r->len++] = 0x00; /* message body format: 8-bit class, 8-bit instance */
  }
}

void dn_init(dn_slave *s, uint8_t mac) {
  memset(s, 0, sizeof *s);
  s->mac = mac;
  s->ack_timer = 16;
  s->ack_retry_limit = 1;
}

static uint16_t group2_id(const dn_slave *s, unsigned message) {
  return (uint16_t)(0x400u | ((unsigned)s->mac << 3) | message);
}

/* The next frame of a reply: whole when it fits, else fragment by fragment
 * (frag bit in the header, then type<<6 | count, then up to 6 body bytes). */
static void next_reply_frame(dn_slave *s, dn_frame *out) {
  out->id = group2_id(s, 3);
  if (!s->fragmenting) {
    out->data[0] = s->reply_hdr;
    memcpy(out->data + 1, s->reply, s->reply_len);
    out->len = (uint8_t)(1u + s->reply_len);
    return;
  }
  {
    const unsigned left = (unsigned)s->reply_len - s->reply_sent;
    const unsigned chunk = left > 6u ? 6u : left;
    const unsigned type = s->reply_sent == 0u ? 0u : (left <= 6u ? 2u : 1u);
    out->data[0] = (uint8_t)(s->reply_hdr | 0x80u);
    out->data[1] = (uint8_t)((type << 6) | (s->fragment_count & 0x3Fu));
    memcpy(out->data + 2, s->reply + s->reply_sent, chunk);
    out->len = (uint8_t)(2u + chunk);
    s->reply_sent = (uint8_t)(s->reply_sent + chunk);
  }
}

/* The master acknowledges a fragment: send the next one, if any. */
static int fragment_ack(dn_slave *s, const dn_frame *in, dn_frame *out) {
  if (!s->fragmenting || in->len < 2u || (in->data[1] >> 6) != 3u ||
      (in->data[1] & 0x3Fu) != (s->fragment_count & 0x3Fu))
    return 0;
  if (s->reply_sent >= s->reply_len) {
    s->fragmenting = 0; /* the last fragment is acknowledged */
    return 0;
  }
  s->fragment_count++;
  next_reply_frame(s, out);
  return 1;
}

static void explicit_request(dn_slave *s, const uint8_t *req, unsigned n, int unconnected, reply *r) {
  const unsigned service = req[0];
  r->body[0] = (uint8_t)(service | EDS_SERVICE_REPLY);
  r->len = 1;
  if (service == EDS_SERVICE_ALLOCATE || service == EDS_SERVICE_RELEASE) {
    allocation_service(s, service, req, n, r);
  } else if (unconnected) {
    error(r, EDS_STATUS_SERVICE_NOT_SUPPORTED); /* the unconnected port only allocates */
  } else if (service != EDS_SERVICE_GET_ATTRIBUTE_SINGLE && service != EDS_SERVICE_SET_ATTRIBUTE_SINGLE) {
    error(r, EDS_STATUS_SERVICE_NOT_SUPPORTED);
  } else if (n < 4u) {
    error(r, EDS_STATUS_NOT_ENOUGH_DATA);
  } else {
    attribute_service(s, service == EDS_SERVICE_SET_ATTRIBUTE_SINGLE, req, n, r);
  }
}

int dn_receive(dn_slave *s, const dn_frame *in, dn_frame *out) {
  unsigned message;
  reply r;
  if ((in->id & 0x600u) != 0x400u || ((in->id >> 3) & 0x3Fu) != s->mac || in->len < 1u) return 0;
  if (!s->online) {
    /* Not on line yet: the first thing a node sends is its duplicate MAC ID
     * check (port 0, vendor, serial); a request arriving meanwhile goes
     * unanswered. The check is modelled as succeeding at once. */
    out->id = group2_id(s, 7);
    out->data[0] = 0x00;
    memcpy(out->data + 1, vendor_id, 2);
    memcpy(out->data + 3, serial_number, 4);
    out->len = 7;
    s->online = 1;
    return 1;
  }
  message = in->id & 7u;
  if (message != 4u && message != 6u) return 0;
  if (message == 4u && !(s->allocated & EDS_ALLOCATE_EXPLICIT)) return 0; /* no explicit connection */
  if (in->data[0] & 0x80u) return fragment_ack(s, in, out);
  if (in->len < 2u) return 0;
  explicit_request(s, in->data + 1, in->len - 1u, message == 6u, &r);
  s->reply_hdr = (uint8_t)(in->data[0] & 0x7Fu);
  memcpy(s->reply, r.body, r.len);
  s->reply_len = r.len;
  s->reply_sent = 0;
  s->fragment_count = 0;
  s->fragmenting = r.len > 7u;
  next_reply_frame(s, out);
  return 1;
}
