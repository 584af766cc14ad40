fn main() {
    println!("rujoco");
}
