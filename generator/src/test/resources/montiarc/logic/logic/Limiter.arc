package logic;

component Limiter(int max) extends Clamp<Integer>(max) {
}
