package org.kicnp.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import picocli.CommandLine;

/**
 * The command lines the documentation writes ({@code ./kicnp VERB … --option …}), checked against a picocli model:
 * every {@code --option} a doc names after a verb (and its sub-command, if any) must be an option of that command.
 * Command lines are taken from code spans, from the lines of fenced code blocks, and from the first column of the
 * README's table of verbs (written without {@code kicnp}). {@code docs/benchmarks.md} is left out: it records past
 * runs, with the options they had then.
 *
 * <p>Public, and in kicnp-cli's test jar, for kicnp-bench's test of the {@code bench} verb against that module's model.
 */
public final class DocumentedOptions {

    /** One option named in a doc: where, the command line as written, the command it was read against. */
    public record Use(String place, String line, String command, String option, boolean known) {
        @Override public String toString() {
            return place + ": '" + option + "' is not an option of '" + command + "' in: " + line;
        }
    }

    private static final Pattern CODE_SPAN = Pattern.compile("`([^`\n]+)`");
    private static final Pattern KICNP = Pattern.compile("(?<![\\w./-])(?:\\./)?kicnp\\s+(\\S.*)");
    private static final Pattern VERB_ROW = Pattern.compile("^\\|\\s*`([a-z][a-z-]*(?:\\s[^`]*)?)`\\s*\\|");

    private DocumentedOptions() {
    }

    /** README.md and every docs/*.md but benchmarks.md, from the repository root. */
    public static List<Path> docs(Path root) {
        List<Path> out = new ArrayList<>(List.of(root.resolve("README.md")));
        try (Stream<Path> s = Files.list(root.resolve("docs"))) {
            s.filter(p -> p.getFileName().toString().endsWith(".md"))
                    .filter(p -> !p.getFileName().toString().equals("benchmarks.md")).sorted().forEach(out::add);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out;
    }

    /**
     * Every option named after one of {@code verbs} in the docs, read against {@code root}: the command line's first
     * word after {@code kicnp} is a verb, and each later word that names a sub-command of the command reached so far
     * goes down into it.
     *
     * @param verbs the verbs to check, by their name after {@code kicnp}
     * @param skipWords how many words of the command line to skip before matching sub-commands of {@code root}
     *                  (1 when {@code root} is the verb itself, as {@code kicnp bench}'s own command line is)
     */
    public static List<Use> uses(List<Path> docs, Path root, List<String> verbs, CommandLine rootCommand, int skipWords) {
        List<Use> out = new ArrayList<>();
        for (Path doc : docs) {
            List<String> lines;
            try {
                lines = Files.readAllLines(doc);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            boolean fenced = false;
            boolean readme = doc.getFileName().toString().equals("README.md");
            for (int i = 0; i < lines.size(); i++) {
                String line = lines.get(i);
                String place = root.relativize(doc) + ":" + (i + 1);
                if (line.strip().startsWith("```")) {
                    fenced = !fenced;
                    continue;
                }
                List<String> commandLines = new ArrayList<>();
                if (fenced) {
                    Matcher m = KICNP.matcher(line);
                    if (m.find()) {
                        commandLines.add(m.group(1));
                    }
                } else {
                    Matcher span = CODE_SPAN.matcher(line);
                    while (span.find()) {
                        Matcher m = KICNP.matcher(span.group(1));
                        if (m.find()) {
                            commandLines.add(m.group(1));
                        }
                    }
                    Matcher row = VERB_ROW.matcher(line);
                    if (readme && row.find()) {
                        commandLines.add(row.group(1).replace("\\|", " "));
                    }
                }
                for (String commandLine : commandLines) {
                    read(place, commandLine, verbs, rootCommand, skipWords, out);
                }
            }
        }
        return out;
    }

    private static void read(String place, String commandLine, List<String> verbs, CommandLine rootCommand,
                             int skipWords, List<Use> out) {
        String[] words = commandLine.strip().split("\\s+");
        if (words.length == 0 || !verbs.contains(words[0])) {
            return;
        }
        CommandLine at = rootCommand;
        String name = "kicnp";
        for (int w = 0; w < words.length; w++) {
            String word = words[w];
            if (word.startsWith("#") || word.equals("&&") || word.equals(";") || word.startsWith(">")) {
                return; // a shell comment, or the next command
            }
            String bare = word.replaceAll("^[\\[(]+", "").replaceAll("[\\])]+$", "");
            if (bare.startsWith("--") && bare.length() > 2) {
                String option = bare.replaceAll("[=,.:;…].*$", "");
                out.add(new Use(place, commandLine, name, option, at.getCommandSpec().findOption(option) != null));
                continue;
            }
            if (w < skipWords) {
                name = name + " " + word;
                continue;
            }
            CommandLine sub = at.getSubcommands().get(bare);
            if (sub != null) {
                at = sub;
                name = name + " " + bare;
            }
        }
    }
}
