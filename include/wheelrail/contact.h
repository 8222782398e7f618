// Forwarding header until the includes name <wheelrail/contact/penalty_contact.h>.
#include <wheelrail/contact/penalty_contact.h>
