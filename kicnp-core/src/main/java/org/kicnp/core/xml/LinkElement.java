package org.kicnp.core.xml;

import java.util.Optional;

/** A LINK element as read: its RELATION and TARGET (either may be missing, which the mapper reports). */
record LinkElement(int line, int column, Optional<Located> relation, Optional<Located> target) {
}
