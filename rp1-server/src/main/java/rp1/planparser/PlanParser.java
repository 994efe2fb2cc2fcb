package rp1.planparser;

import java.io.IOException;
import java.util.Map;
import java.util.function.BiFunction;

import rp1.rossum.RsFeet;
import rp1.rossum.RsInches;
import rp1.rossum.RsKilometers;
import rp1.rossum.RsMeters;
import rp1.rossum.RsObject;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsUnits;

/**
 * Reads the statements of a floor plan (behavior.md section 1.3): the general specifications
 * {@code units} and {@code caption}, and the object declarations, which become the plan's objects in
 * file order. The first error ends the parse.
 */
final class PlanParser {
    private static final Map<String, BiFunction<String, RsPlan, Declaration>> DECLARATIONS = Map.of(
            "wall", WallDeclaration::new,
            "obstacle", PolygonDeclaration::obstacle,
            "paint", PolygonDeclaration::paint,
            "target", PointDeclaration::target,
            "placement", PointDeclaration::placement,
            "node", PointDeclaration::node,
            "link", LinkDeclaration::new,
            "bitmap", BitmapDeclaration::new);
    private static final String DECLARATION_KEYWORDS =
            "wall, obstacle, target, placement, paint, node, link or bitmap";

    private final PlanLexer lexer;
    private final ValueReader values;
    private final RsPlan plan;

    PlanParser(PlanLexer lexer, String fileName) {
        this.lexer = lexer;
        this.values = new ValueReader(lexer);
        this.plan = new RsPlan(fileName);
    }

    /** Reads every statement and returns the plan. */
    RsPlan parse() throws IOException, RsParsingException {
        Token t = lexer.next();
        while (!t.isEnd()) {
            statement(t);
            t = lexer.next();
        }
        if (plan.getObjectCount() == 0) {
            throw lexer.error(t, "Empty floor plan: expected at least one declaration (" + DECLARATION_KEYWORDS
                    + "), found end of file");
        }
        return plan;
    }

    private void statement(Token first) throws IOException, RsParsingException {
        lexer.startStatement(first);
        if (!first.isIdentifier()) {
            throw lexer.error(first, "Invalid syntax where identifier expected (a keyword that starts a"
                    + " statement, such as units, caption or wall), found " + first.describe());
        }
        Token second = lexer.next();
        if (second.isEnd()) {
            throw lexer.error(second, "Premature end-of-file encountered within statement " + first.text());
        }
        String keyword = first.text();
        if (keyword.equals("units")) {
            units();
        } else if (keyword.equals("caption")) {
            plan.setCaption(values.string());
            endOfSpecification();
        } else if (second.is(':')) {
            throw lexer.error(first, "Unrecognized specification keyword: " + keyword
                    + " (the general specifications are units and caption)");
        } else if (keyword.equals("doorway")) {
            throw lexer.error(first, "doorway declarations are not supported (RP1 never implemented them;"
                    + " leave a gap between walls instead)");
        } else if (DECLARATIONS.containsKey(keyword)) {
            declaration(DECLARATIONS.get(keyword), second);
        } else {
            throw lexer.error(first, "Unrecognized keyword where declaration expected: " + keyword
                    + " (expected " + DECLARATION_KEYWORDS + ")");
        }
    }

    /** {@code units} has consumed the token after it unchecked (normally the colon), as the original does. */
    private void units() throws IOException, RsParsingException {
        Token t = values.identifier("Invalid syntax where units specification expected (meters, feet, inches"
                + " or kilometers)");
        RsUnits units = unitsNamed(t.text());
        if (units == null) {
            throw lexer.error(t, "Invalid or unimplemented units specification " + t.text()
                    + " (expected meters, feet, inches or kilometers)");
        }
        values.setUnits(units);
        plan.setUnits(units);
        endOfSpecification();
    }

    private static RsUnits unitsNamed(String name) {
        switch (name) {
            case "meters":
                return new RsMeters();
            case "feet":
                return new RsFeet();
            case "inches":
                return new RsInches();
            case "kilometers":
                return new RsKilometers();
            default:
                return null;
        }
    }

    private void endOfSpecification() throws IOException, RsParsingException {
        values.symbol(';', "Invalid syntax where semi-colon expected");
    }

    private void declaration(BiFunction<String, RsPlan, Declaration> kind, Token nameToken)
            throws IOException, RsParsingException {
        Declaration d = kind.apply(name(nameToken), plan);
        Token open = lexer.nextInStatement();
        if (!open.is('{')) {
            throw lexer.error(open, "Invalid syntax where open brace expected in declaration, found "
                    + open.describe());
        }
        while (true) {
            Token t = lexer.nextInStatement();
            if (t.is('}')) {
                for (RsObject o : d.objects(t, lexer)) {
                    add(d.keyword(), o, t);
                }
                return;
            }
            if (t.isIdentifier()) {
                specification(d, t);
            } else if (d.strict()) {
                throw lexer.error(t, "Invalid syntax where object specification expected (" + d.acceptedItems()
                        + "), found " + t.describe());
            }
        }
    }

    /** One {@code name: value;} inside a declaration; the name has been read. */
    private void specification(Declaration d, Token item) throws IOException, RsParsingException {
        values.symbol(':', d.strict() ? "Invalid syntax where ':' expected in object specification"
                : "Invalid syntax in specification (colon expected)");
        if (!d.item(item, values)) {
            String article = "aeiou".indexOf(d.keyword().charAt(0)) >= 0 ? "an " : "a ";
            throw lexer.error(item, "Invalid object specification: " + item.text() + " (" + article
                    + d.keyword() + " declaration accepts " + d.acceptedItems() + ")");
        }
        values.symbol(';', d.strict() ? "Invalid syntax where ';' expected"
                : "Invalid syntax where semi-colon expected");
    }

    /**
     * The declared name: an identifier as written, an integer n as the synthesized name for n (which
     * raises the serial counter), and otherwise a fresh synthesized name (the token is not a name and
     * is read again as the opening brace).
     */
    private String name(Token t) throws RsParsingException {
        String name;
        if (t.isIdentifier()) {
            name = t.text();
        } else if (t.kind() == Token.Kind.INTEGER) {
            name = plan.synthesizeName(t.integer());
            plan.maximizeSerialNumber(t.integer());
        } else {
            lexer.pushBack(t);
            name = plan.synthesizeName();
        }
        if (plan.getObjectByName(name) != null) {
            throw lexer.error(t, "Duplicate object name " + name + ": names must be unique among all objects");
        }
        return name;
    }

    private void add(String keyword, RsObject object, Token close) throws RsParsingException {
        if (plan.getObjectCount() == ParserLimits.MAX_OBJECTS) {
            throw lexer.error(close, "Too many objects: a plan may declare at most " + ParserLimits.MAX_OBJECTS);
        }
        checkWithinLimit(keyword, object, close);
        if (object.getName() != null && plan.getObjectByName(object.getName()) != null) {
            throw lexer.error(close, "Duplicate object name " + object.getName() + ": " + keyword
                    + " names its walls NAME_1, NAME_2, ... and an earlier object has this name");
        }
        plan.addObject(object);
    }

    /**
     * Every number was within the limit, but a radius, a thickness or an offset can carry an object
     * beyond it: the object as a whole must lie inside it too.
     */
    private void checkWithinLimit(String keyword, RsObject object, Token close) throws RsParsingException {
        RsRectangle b = object.getBounds();
        if (b.isPopulated() && !(withinLimit(b.x) && withinLimit(b.y) && withinLimit(b.x + b.width)
                && withinLimit(b.y + b.height))) {
            throw lexer.error(close, "Object out of range: " + keyword + " " + object.getName()
                    + " covers x " + b.x + " to " + (b.x + b.width) + " m, y " + b.y + " to " + (b.y + b.height)
                    + " m, beyond " + ValueReader.LIMIT_IN_WORDS);
        }
    }

    private static boolean withinLimit(double coordinate) {
        return Math.abs(coordinate) <= ParserLimits.MAX_COORDINATE;
    }
}
