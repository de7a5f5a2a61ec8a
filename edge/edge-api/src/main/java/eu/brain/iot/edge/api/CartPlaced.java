package eu.brain.iot.edge.api;

/** A robot put down the cart it carried. */
public class CartPlaced extends RobotEvent {

    public String cartId;
    public int x;
    public int y;
}
