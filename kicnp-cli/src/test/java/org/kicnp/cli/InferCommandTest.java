package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class InferCommandTest {
    private static final String TABLE5 = Path.of("..", "scenarios", "table5").toString();
    private static final String NEW_USER = """
            <FRAME><NAME>userA</NAME><ISA>NewUser</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>""";

    private record Result(int code, String out, String err) { }

    private static Result run(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            int code = Main.run(args);
            return new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    @Test
    void infer_withInlineNewUser_printsTheAskUserNameInstanceAndItsSpeechAction() {
        Result r = run("infer", TABLE5, "--assert", NEW_USER);
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("(AskUserName) mUser=userA mMouth=RobovieMouth")
                .contains("Robovie (via RobovieMouth) say [How are you! I have never seen you before. What is your name?]");
    }

    @Test
    void infer_withTraceAndAsk_printsJsonLinesAndAnswers(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("user.xml");
        Files.writeString(file, NEW_USER);
        Result r = run("infer", TABLE5, "--assert", file.toString(), "--trace", "--ask", "AskUserName");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("{\"event\":\"FactAsserted\",\"instance\":\"userA\"")
                .contains("{\"event\":\"Fired\",\"frame\":\"AskUserName\"")
                .contains("Answers for AskUserName:");
    }

    @Test
    void infer_withWhyNot_saysWhichSlotHasNoCandidate_andThatAFiredBindingIsRefracted() {
        Result r = run("infer", TABLE5, "--assert", NEW_USER, "--why-not", "Greeting", "--why-not", "AskUserName");

        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("Why not Greeting: 'Greeting' cannot fire: nothing can fill its slot 'mUser' "
                        + "(there is no instance of 'KnownUser').")
                .contains("  slot mMouth (Mouth, COND_ANY): RobovieMouth")
                .contains("Why not AskUserName: 'AskUserName' has 1 binding: 1 blocked.")
                .contains("  mUser=userA mMouth=RobovieMouth -> blocked: refraction: this binding has already fired");
    }

    @Test
    void infer_withWhyNotOfAFrameThatIsNotThere_orNotABehaviorFrame_failsInWords() {
        Result unknown = run("infer", TABLE5, "--why-not", "Nope");
        Result notBehavior = run("infer", TABLE5, "--why-not", "User");

        assertThat(unknown.code()).isEqualTo(1);
        assertThat(unknown.err()).contains("infer: --why-not names 'Nope', which is not a frame of the knowledge base.");
        assertThat(unknown.out()).doesNotContain("Created");
        assertThat(notBehavior.code()).isEqualTo(1);
        assertThat(notBehavior.err()).contains("infer: Frame 'User' is not a behavior frame: it has no required "
                + "instance slot, so the engine never fires it.");
    }

    @Test
    void infer_onADirectoryWithoutKnowledgeFiles_failsWithAMessage(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("notes.txt"), "not a knowledge file");

        Result r = run("infer", dir.toString(), "--assert", NEW_USER);

        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("infer: no knowledge files (*.xml) found in [" + dir + "].");
        assertThat(r.out()).doesNotContain("Created");
    }

    @Test
    void infer_withAssertBeforeTheKnowledgeBase_saysThatAssertTookItAndHowToWriteIt() {
        Result r = run("infer", "--assert", "stimulus.xml", TABLE5);

        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("Missing the knowledge base (KB): --assert takes every value after it")
                .contains("stimulus.xml " + TABLE5 + " here").contains("kicnp infer KB --assert FILE_OR_XML...");
    }

    @Test
    void infer_withoutAnyArgument_isAUsageErrorNamingTheKnowledgeBase() {
        Result r = run("infer");

        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("Missing the knowledge base (KB).");
    }

    @Test
    void infer_whenAScriptConditionFails_warnsOnceNamingFrameAndSlot(@TempDir Path dir) throws Exception {
        Path kb = Files.writeString(dir.resolve("kb.xml"), """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Cup</NAME><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>size</NAME><TYPE>TYPE_INT</TYPE></SLOT></SLOTLIST></FRAME>
                  <FRAME><NAME>Spill</NAME><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>mCup</NAME><TYPE>TYPE_INSTANCE</TYPE><ARGUMENT>Cup</ARGUMENT>
                      <REQUIRED>TRUE</REQUIRED><CONDITION>js: s.mCup.nothing.size &gt; 1</CONDITION></SLOT></SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);

        Result r = run("infer", kb.toString(), "--assert",
                "<FRAME><NAME>cup1</NAME><ISA>Cup</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>",
                "<FRAME><NAME>cup2</NAME><ISA>Cup</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>");

        assertThat(r.code()).as(r.err()).isZero();
        String warning = "The script condition of slot 'mCup' of frame 'Spill' failed, so it counts as false";
        assertThat(r.err()).contains(warning);
        assertThat(r.err().split(java.util.regex.Pattern.quote(warning), -1)).as("logged once for both cups").hasSize(2);
        assertThat(r.out()).doesNotContain("(Spill)");
    }

    @Test
    void infer_withAnEmptyAssert_isAUsageErrorRatherThanAssertingTheWorkingDirectory() {
        Result r = run("infer", TABLE5, "--assert", NEW_USER, "");

        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("--assert got an empty value; give an XML file or XML text starting with '<'.");
        assertThat(r.out()).doesNotContain("Created");
    }

    @Test
    void infer_withAnEmptyKnowledgeBasePath_failsRatherThanLoadingTheWorkingDirectory() {
        Result r = run("infer", TABLE5, "", "--assert", NEW_USER);

        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("infer: '':1:1: An empty path names no file or directory; write '.' for the "
                + "current directory.");
        assertThat(r.out()).doesNotContain("Created");
    }

    @Test
    void infer_askingForAFrameThatIsNotAClass_failsWithAMessageAndNoHalfReport() {
        Result unknown = run("infer", TABLE5, "--assert", NEW_USER, "--ask", "AskUserName", "--ask", "Nope");
        Result instance = run("infer", TABLE5, "--ask", "RobovieMouth");

        assertThat(unknown.code()).isEqualTo(1);
        assertThat(unknown.err()).contains("infer: --ask names 'Nope', which is not a frame of the knowledge base.");
        assertThat(unknown.out()).doesNotContain("Answers for");
        assertThat(instance.code()).isEqualTo(1);
        assertThat(instance.err()).contains("infer: --ask takes a class, but 'RobovieMouth' is an instance.");
        assertThat(instance.out()).doesNotContain("Answers for");
    }

    @Test
    void infer_whenTheKnowledgeBaseHasXmlErrorsAndFrameProblems_reportsBothAtOnce(@TempDir Path dir) throws Exception {
        Path kb = Files.writeString(dir.resolve("kb.xml"), """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Cup</NAME><ISINSTANCE>perhaps</ISINSTANCE></FRAME>
                  <FRAME><NAME>Spill</NAME><ISA>Acident</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);

        Result r = run("infer", kb.toString(), "--assert", NEW_USER);

        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains(kb + ":2:26: Frame 'Cup' has ISINSTANCE 'perhaps', which is not a boolean")
                .contains(kb + ":3:28: Frame 'Spill' is a kind of 'Acident', which is not defined.");
    }

    @Test
    void infer_whenAnAssertHoldsNoFrame_failsRatherThanRunningOnNothing(@TempDir Path dir) throws Exception {
        Path empty = Files.writeString(dir.resolve("none.xml"), "<KNOWLEDGEBASE>\n</KNOWLEDGEBASE>\n");

        Result text = run("infer", TABLE5, "--assert", "<KNOWLEDGEBASE/>");
        Result file = run("infer", TABLE5, "--assert", NEW_USER, empty.toString());

        assertThat(text.code()).isEqualTo(1);
        assertThat(text.err()).contains("infer: --assert <KNOWLEDGEBASE/> holds no FRAME element; nothing was asserted.");
        assertThat(text.out()).doesNotContain("Created");
        assertThat(file.code()).isEqualTo(1);
        assertThat(file.err()).contains("infer: --assert " + empty + " holds no FRAME element");
    }

    @Test
    void infer_withMaxFiringsBelowOne_isAUsageErrorNamingTheOption() {
        Result r = run("infer", TABLE5, "--max-firings", "-5");

        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("--max-firings must be at least 1, not -5.");
    }

    @Test
    void infer_withMaxDepth_stopsAKnowledgeBaseThatFeedsItselfThere_namingTheFrame(@TempDir Path dir) throws Exception {
        Path kb = Files.writeString(dir.resolve("echo.xml"), """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Thing</NAME><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                  <FRAME><NAME>Echo</NAME><ISA>Thing</ISA><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>mIn</NAME><TYPE>TYPE_INSTANCE</TYPE><ARGUMENT>Thing</ARGUMENT>
                      <REQUIRED>TRUE</REQUIRED></SLOT></SLOTLIST></FRAME>
                </KNOWLEDGEBASE>
                """);
        String t0 = "<FRAME><NAME>t0</NAME><ISA>Thing</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>";

        Result r = run("infer", kb.toString(), "--max-depth", "20", "--assert", t0);
        Result usage = run("infer", kb.toString(), "--max-depth", "0");

        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("infer: Inference stopped: 'Echo' would derive an instance resting on 20 derived "
                + "instances, each made from the one before, so the knowledge base feeds itself; the frames firing "
                + "most were 'Echo'.");
        assertThat(usage.code()).isEqualTo(2);
        assertThat(usage.err()).contains("--max-depth must be at least 1, not 0.");
    }

    @Test
    void infer_whenAssertingAClass_failsWithAMessage() {
        Result r = run("infer", TABLE5, "--assert",
                "<FRAME><NAME>Ghost</NAME><ISA>User</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("infer: --assert takes instance frames, but 'Ghost'").contains("is a class.");
    }

    @Test
    void infer_help_describesTheOptions() {
        Result r = run("infer", "--help");
        assertThat(r.code()).isZero();
        assertThat(r.out()).contains("--assert").contains("--trace").contains("--ask").contains("--why-not");
    }

    @Test
    void infer_whenKnowledgeBaseIsMissing_failsNamingThePath() {
        Result r = run("infer", "no-such-dir");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("no-such-dir");
    }

    @Test
    void infer_withExpectationsAllMet_printsEachAsPass_andExitsZero() {
        Result r = run("infer", TABLE5, "--assert", NEW_USER, "--expect", "AskUserName=1", "--expect-none",
                "Greeting", "--expect-action", "Robovie:say", "--expect", "NewUser");

        assertThat(r.code()).as(r.err() + r.out()).isZero();
        assertThat(r.out()).contains("Expectations:")
                .containsPattern("  pass  1 instance of AskUserName: 1 \\(AskUserName-\\d+\\)")
                .contains("  pass  no instance of Greeting: none")
                .containsPattern("  pass  action Robovie:say: 1 issued \\(\\S+ by AskUserName-\\d+\\)")
                .contains("  pass  an instance of NewUser: 1 (userA)")
                .contains("All 4 expectations met.");
    }

    @Test
    void infer_withAnExpectationNotMet_printsFail_withWhyTheFrameDidNotFire_andExits3() {
        Result r = run("infer", TABLE5, "--assert", NEW_USER, "--expect", "Greeting", "--expect", "AskUserName=2",
                "--expect-action", "Pino:dance", "--expect-none", "AskUserName");

        assertThat(r.code()).as(r.err()).isEqualTo(3);
        assertThat(r.out()).contains("  FAIL  an instance of Greeting: none")
                .contains("        why not: 'Greeting' cannot fire: nothing can fill its slot 'mUser' (there is no "
                        + "instance of 'KnownUser').")
                .containsPattern("  FAIL  2 instances of AskUserName: 1 \\(AskUserName-\\d+\\)")
                .contains("  FAIL  action Pino:dance: not issued (issued: Robovie:head, Robovie:say)")
                .containsPattern("  FAIL  no instance of AskUserName: 1 \\(AskUserName-\\d+\\)")
                .contains("4 of 4 expectations not met.");
    }

    @Test
    void infer_withAnExpectationOnAMisspeltClass_orABadCount_failsInWords_notAsAPass() {
        Result misspelt = run("infer", TABLE5, "--assert", NEW_USER, "--expect-none", "Greting");
        Result badCount = run("infer", TABLE5, "--expect", "Greeting=many");
        Result badAction = run("infer", TABLE5, "--expect-action", "Robovie:");

        assertThat(misspelt.code()).isEqualTo(1);
        assertThat(misspelt.err()).contains("infer: --expect-none names 'Greting', which is not a frame of the "
                + "knowledge base.");
        assertThat(misspelt.out()).doesNotContain("pass");
        assertThat(badCount.code()).isEqualTo(2);
        assertThat(badCount.err()).contains("--expect 'Greeting=many' is not CLASS or CLASS=N");
        assertThat(badAction.code()).isEqualTo(2);
        assertThat(badAction.err()).contains("--expect-action 'Robovie:' is not ACTION or ROBOT:ACTION.");
    }
}
