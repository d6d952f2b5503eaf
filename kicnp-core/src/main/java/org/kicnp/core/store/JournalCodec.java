package org.kicnp.core.store;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlWriter;
import org.kicnp.core.xml.SourcedFrame;

/**
 * Turns a {@link JournalRecord} into the payload bytes of one journal entry and back. A put carries the frame as a
 * small document of the paper's XML format, so the journal needs no second frame format: what the XML reader
 * accepts, the journal can hold. Layout: version (long), op count (int), then per op a tag byte ('P' or 'D') and a
 * length-prefixed UTF-8 string (the XML document or the name).
 */
final class JournalCodec {
    private static final byte PUT = 'P';
    private static final byte DELETE = 'D';

    private JournalCodec() {
    }

    static byte[] encode(JournalRecord record) {
        try {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream(256);
            DataOutputStream out = new DataOutputStream(bytes);
            out.writeLong(record.version());
            out.writeInt(record.ops().size());
            for (JournalRecord.Op op : record.ops()) {
                switch (op) {
                    case JournalRecord.Put p -> {
                        out.writeByte(PUT);
                        writeString(out, xmlOf(p.frame()));
                    }
                    case JournalRecord.Delete d -> {
                        out.writeByte(DELETE);
                        writeString(out, d.name());
                    }
                }
            }
            out.flush();
            return bytes.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Reads a payload whose checksum was already verified, so any problem here is a bug or a foreign file rather
     * than a torn write.
     *
     * @param where names the record in messages, such as {@code journal-…0003 at byte 512}
     * @param context the knowledge base the XML reader resolves names against
     * @param above the frames as the records before this one left them, by name: a put inherits declarations (a list
     *     slot's ARGUMENT) from them, not from {@code context}, which does not hold the journal's changes yet
     */
    static JournalRecord decode(byte[] payload, String where, KnowledgeBase context,
            Function<String, Optional<Frame>> above) {
        try {
            DataInputStream in = new DataInputStream(new ByteArrayInputStream(payload));
            long version = in.readLong();
            int count = in.readInt();
            if (count < 0 || count > payload.length) {
                throw new StoreException("The journal record " + where + " claims " + count + " operations.");
            }
            List<JournalRecord.Op> ops = new ArrayList<>(count);
            for (int i = 0; i < count; i++) {
                byte tag = in.readByte();
                String text = readString(in, payload.length);
                ops.add(switch (tag) {
                    case PUT -> new JournalRecord.Put(frameOf(text, where, context, above));
                    case DELETE -> new JournalRecord.Delete(text);
                    default -> throw new StoreException("The journal record " + where + " has an unknown operation tag "
                            + tag + ".");
                });
            }
            if (in.available() != 0) {
                throw new StoreException("The journal record " + where + " has " + in.available()
                        + " bytes after its last operation.");
            }
            return new JournalRecord(version, ops);
        } catch (IOException e) {
            throw new StoreException("The journal record " + where + " ends in the middle of an operation.", e);
        }
    }

    private static String xmlOf(Frame frame) throws IOException {
        StringWriter w = new StringWriter(256);
        KnowledgeXmlWriter.write(List.of(frame), w);
        return w.toString();
    }

    private static Frame frameOf(String xml, String where, KnowledgeBase context,
            Function<String, Optional<Frame>> above) {
        List<SourcedFrame> frames = KnowledgeLoader.parseTextAbove(xml, where, context, above);
        if (frames.size() != 1) {
            throw new StoreException("The journal record " + where + " holds " + frames.size()
                    + " frames in one put instead of one.");
        }
        return frames.get(0).frame();
    }

    private static void writeString(DataOutputStream out, String s) throws IOException {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        out.writeInt(b.length);
        out.write(b);
    }

    private static String readString(DataInputStream in, int limit) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > limit) {
            throw new IOException("String length " + n + " out of range.");
        }
        return new String(in.readNBytes(n), StandardCharsets.UTF_8);
    }
}
