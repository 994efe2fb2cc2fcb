package rp1.planparser;

import java.io.IOException;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsPlan;

/**
 * {@code link}: a navigation link between two nodes declared earlier, {@code nodes: A, B;}
 * (required). Its geometry is the segment between the nodes, so it takes no geometry specification.
 */
final class LinkDeclaration extends Declaration {
    private final RsPlan plan;
    private RsNavNode n0;
    private RsNavNode n1;

    LinkDeclaration(String name, RsPlan plan) {
        super(new RsNavLink(name, plan), false, "nodes");
        this.plan = plan;
    }

    @Override
    protected boolean specificItem(Token item, ValueReader in) throws IOException, RsParsingException {
        if (item.text().equals("geometry")) {
            throw in.lexer().error(item, "Link objects do not take a geometry specification: a link runs between"
                    + " its nodes, given as nodes: A, B;");
        }
        if (!item.text().equals("nodes")) {
            return false;
        }
        RsNavNode first = node(in);
        in.symbol(',', "Invalid syntax where comma expected in nodes specification");
        n1 = node(in);
        n0 = first;
        return true;
    }

    private RsNavNode node(ValueReader in) throws IOException, RsParsingException {
        Token t = in.identifier("Invalid syntax where node identifier expected");
        RsObject o = plan.getObjectByName(t.text());
        if (o == null) {
            throw in.lexer().error(t, "Specified node was not defined \"" + t.text()
                    + "\": expected the name of a node declared earlier in the plan");
        }
        if (!(o instanceof RsNavNode)) {
            throw in.lexer().error(t, "Specified identifier is not a node \"" + t.text() + "\": it names a "
                    + o.getClassName());
        }
        return (RsNavNode) o;
    }

    @Override
    RsObject finish(Token close, PlanLexer lexer) throws RsParsingException {
        if (n0 == null) {
            throw lexer.error(close, "Missing nodes specification: a link needs nodes: A, B;");
        }
        RsNavLink link = (RsNavLink) object;
        link.setNodes(n0, n1);
        n0.addLink(link);
        n1.addLink(link);
        return link;
    }
}
